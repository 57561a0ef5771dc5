// Optical imperfections of the simulated cameras, applied to the rendered
// irradiance (CV_32FC3, grey levels 0..255 at gain 1) before the sensor: blur
// (a Gaussian point-spread function and a horizontal motion streak),
// vignetting, and the variance-of-the-Laplacian sharpness measure.
#pragma once

#include <opencv2/core.hpp>

#include "pmap/sim/camera_model.h"

namespace pmap::sim {

/// Convolves `image` with a Gaussian of `sigma_px` (skipped below 0.05 px) and
/// then with a horizontal box of `motion_length_px` pixels (fractional end
/// taps; skipped at <= 1 px). Borders reflect. Same type as the input.
cv::Mat blurImage(const cv::Mat& image, double sigma_px, double motion_length_px);

/// Per-pixel light fall-off 1 - strength * (r / r_corner)^2 (CV_32FC1), r the
/// distance of the pixel centre to the principal point, r_corner that of the
/// farthest image corner.
cv::Mat vignettingMap(const PinholeIntrinsics& k, double strength);

/// Variance of the 3x3 Laplacian ([0 1 0; 1 -4 1; 0 1 0]) of the image's grey
/// levels (BGR weights 0.114, 0.587, 0.299); 8-bit or float, 1 or 3 channels.
/// Larger = sharper (for the same scene).
double laplacianVariance(const cv::Mat& image);

}  // namespace pmap::sim
