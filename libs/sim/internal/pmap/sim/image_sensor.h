// The image sensor of the simulated cameras: turns the optical image
// (irradiance in grey levels at gain 1, CV_32FC3) into the 8-bit image the
// camera writes. Per channel value x and pixel falloff w (vignetting):
//   signal = gain * w * x                       (exposure, grey levels)
//   raw    = signal + offset_dn + n,  n ~ N(0, read_sigma_dn^2 + max(signal, 0) * 255 /
//   full_well_e) out    = round(255 * (clip(raw, 0, 255) / 255)^(1 / gamma))
// Noise is independent per channel and pixel and seeded.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>

#include "pmap/sim/camera_imaging_options.h"

namespace pmap::sim {

/// The exposure of one frame.
struct FrameExposure {
  double gain = 1.0;
  double offset_dn = 0.0;
  double gamma = 1.0;
};

struct SensorReadout {
  cv::Mat image;                    ///< CV_8UC3
  double saturated_fraction = 0.0;  ///< share of channel values clipped at 255
};

/// `falloff` is CV_32FC1 of the image size, or empty for none.
SensorReadout readSensor(const cv::Mat& irradiance, const cv::Mat& falloff,
                         const CameraNoiseOptions& noise, const FrameExposure& exposure,
                         std::uint64_t seed);

}  // namespace pmap::sim
