// Luminance of the texture stage's colours.
#pragma once

#include <opencv2/core.hpp>

namespace pmap::texture {

/// Luminance (0..255) of a BGR value, Rec. 601 weights.
inline float luminance(const cv::Vec3f& bgr) {
  return 0.114f * bgr[0] + 0.587f * bgr[1] + 0.299f * bgr[2];
}

}  // namespace pmap::texture
