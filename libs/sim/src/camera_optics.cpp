#include "pmap/sim/camera_optics.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace pmap::sim {
namespace {

/// A centred box of `length` pixels sampled on integer taps: each tap weighs
/// the overlap of its pixel [j - 0.5, j + 0.5] with [-length/2, length/2].
cv::Mat motionKernel(double length) {
  const double half = 0.5 * length;
  const int taps = static_cast<int>(std::ceil(half - 0.5));
  cv::Mat kernel(1, 2 * taps + 1, CV_32FC1);
  for (int j = -taps; j <= taps; ++j) {
    const double overlap = std::min(j + 0.5, half) - std::max(j - 0.5, -half);
    kernel.at<float>(0, j + taps) = static_cast<float>(std::max(0.0, overlap) / length);
  }
  return kernel;
}

}  // namespace

cv::Mat blurImage(const cv::Mat& image, double sigma_px, double motion_length_px) {
  cv::Mat out = image;  // never written in place: the caller keeps `image`
  if (sigma_px >= 0.05) {
    cv::Mat smooth;
    cv::GaussianBlur(image, smooth, cv::Size(0, 0), sigma_px, sigma_px, cv::BORDER_REFLECT_101);
    out = smooth;
  }
  if (motion_length_px > 1.0) {
    cv::Mat streaked;
    cv::filter2D(out, streaked, -1, motionKernel(motion_length_px), cv::Point(-1, -1), 0.0,
                 cv::BORDER_REFLECT_101);
    out = streaked;
  }
  return out;
}

cv::Mat vignettingMap(const PinholeIntrinsics& k, double strength) {
  cv::Mat map(k.height_px, k.width_px, CV_32FC1);
  const double r_corner2 =
      std::max(k.cx * k.cx, (k.width_px - 1 - k.cx) * (k.width_px - 1 - k.cx)) +
      std::max(k.cy * k.cy, (k.height_px - 1 - k.cy) * (k.height_px - 1 - k.cy));
  for (int v = 0; v < k.height_px; ++v) {
    auto* row = map.ptr<float>(v);
    for (int u = 0; u < k.width_px; ++u) {
      const double r2 = (u - k.cx) * (u - k.cx) + (v - k.cy) * (v - k.cy);
      row[u] = static_cast<float>(1.0 - strength * r2 / std::max(r_corner2, 1e-9));
    }
  }
  return map;
}

double laplacianVariance(const cv::Mat& image) {
  cv::Mat f;
  image.convertTo(f, CV_32F);
  cv::Mat grey;
  if (f.channels() == 3) {
    cv::cvtColor(f, grey, cv::COLOR_BGR2GRAY);
  } else {
    grey = f;
  }
  cv::Mat lap;
  cv::Laplacian(grey, lap, CV_32F, 1, 1.0, 0.0, cv::BORDER_REFLECT_101);
  cv::Scalar mean, stddev;
  cv::meanStdDev(lap, mean, stddev);
  return stddev[0] * stddev[0];
}

}  // namespace pmap::sim
