// From a rendered view to the image a simulated camera writes: the per-frame
// imperfections (drawn from the camera options and a per-frame seed) and the
// pipeline lens distortion -> blur -> vignetting -> exposure -> sensor noise ->
// clipping -> tone curve -> 8 bits (doc/simulator.md, "Image formation").
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>

#include "pmap/sim/camera_model.h"
#include "pmap/sim/image_sensor.h"
#include "pmap/sim/lens_distortion.h"
#include "pmap/sim/sensor_options.h"

namespace pmap::sim {

/// The imperfections of one frame.
struct FrameEffects {
  FrameExposure exposure;
  double blur_sigma_px = 0.0;   ///< Gaussian sigma: PSF, plus defocus in quadrature, pixels
  double motion_blur_px = 0.0;  ///< horizontal streak length, pixels (0 = none)
  bool blurred = false;         ///< a blur event (defocus or motion) was drawn
};

/// Draws a frame's effects from `options` (uniformly within each interval;
/// a blur event with probability blurred_fraction). Same seed, same effects.
FrameEffects drawFrameEffects(const CameraOptions& options, std::uint64_t seed);

/// Measurements of a developed frame.
struct FrameQuality {
  /// Variance of the Laplacian of the noise-free blurred image over that of
  /// the noise-free unblurred one (1 = as sharp as the renderer; 1 if flat).
  double sharpness = 1.0;
  double laplacian_var = 0.0;       ///< variance of the Laplacian of the written 8-bit image
  double saturated_fraction = 0.0;  ///< share of channel values clipped at 255
};

struct DevelopedFrame {
  cv::Mat image;  ///< CV_8UC3, the output size
  FrameQuality quality;
};

/// What the ground truth records about one written image.
struct ImageRecord {
  std::string file;  ///< file name in PREFIX_Images/
  std::string label;
  int index = 0;  ///< image index of that camera
  double timestamp_s = 0.0;
  FrameEffects effects;
  FrameQuality quality;
};

class ImagingPipeline {
 public:
  /// Throws ConfigError if the lens distortion cannot be rendered.
  explicit ImagingPipeline(const CameraOptions& options);

  /// The cameras' intrinsics, with the lens distortion.
  const PinholeIntrinsics& intrinsics() const { return intrinsics_; }
  /// The ideal pinhole canvas the renderer must fill (larger if distorted).
  const PinholeIntrinsics& renderIntrinsics() const { return warp_.renderIntrinsics(); }

  /// The noise-free optical image at the output size (distortion applied).
  cv::Mat opticalImage(const cv::Mat& render) const { return warp_.apply(render); }
  /// Develops a render of renderIntrinsics() (CV_32FC3); `noise_seed` seeds the sensor noise.
  DevelopedFrame develop(const cv::Mat& render, const FrameEffects& effects,
                         std::uint64_t noise_seed) const;

 private:
  CameraNoiseOptions noise_;
  PinholeIntrinsics intrinsics_;
  LensWarp warp_;
  cv::Mat falloff_;  ///< vignetting, CV_32FC1 (empty: none)
};

}  // namespace pmap::sim
