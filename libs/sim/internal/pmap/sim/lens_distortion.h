// Radial-tangential ("plumb bob") lens distortion, the model of MRPT's
// TCamera::dist and OpenCV, on normalised image coordinates (x, y) = (X/Z, Y/Z):
//   r2 = x^2 + y^2,  radial = 1 + k1 r2 + k2 r2^2 + k3 r2^3
//   x_d = x radial + 2 p1 x y + p2 (r2 + 2 x^2)
//   y_d = y radial + p1 (r2 + 2 y^2) + 2 p2 x y
// and pixel (u, v) = (cx + fx x_d, cy + fy y_d). The simulator renders an ideal
// pinhole view on a canvas large enough for the undistorted rays of every
// output pixel and resamples it through the inverse map (LensWarp).
#pragma once

#include <Eigen/Core>
#include <array>
#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "pmap/sim/camera_model.h"

namespace pmap::sim {

/// Coefficients k1, k2, p1, p2, k3.
using DistortionCoefficients = std::array<double, 5>;

/// The distorted normalised coordinates of the ideal ray (x, y).
Eigen::Vector2d distortNormalised(const DistortionCoefficients& d, const Eigen::Vector2d& xy);

/// The ideal ray whose distorted image is `xy_d` (Newton's method), or nothing
/// if it does not converge.
std::optional<Eigen::Vector2d> undistortNormalised(const DistortionCoefficients& d,
                                                   const Eigen::Vector2d& xy_d);

/// Checks that the distortion is one-to-one over an image of intrinsics `k`
/// (the radial profile increases up to beyond the image corners) and that the
/// undistorted field of view stays renderable (within 3x the image size).
bool distortionIsUsable(const PinholeIntrinsics& k, const DistortionCoefficients& d,
                        std::string* why);

/// The resampling from an ideal pinhole render to the distorted image.
class LensWarp {
 public:
  /// `output` carries the distortion; throws ConfigError if it is unusable.
  explicit LensWarp(const PinholeIntrinsics& output);

  /// The pinhole canvas to render (no distortion; same fx, fy; larger if needed).
  const PinholeIntrinsics& renderIntrinsics() const { return render_; }
  /// Resamples a render of renderIntrinsics() into the output image (bilinear).
  /// Without distortion it returns `render` unchanged.
  cv::Mat apply(const cv::Mat& render) const;

 private:
  PinholeIntrinsics render_;
  cv::Mat map_u_;  ///< CV_32FC1: render column of every output pixel (empty: identity)
  cv::Mat map_v_;
};

}  // namespace pmap::sim
