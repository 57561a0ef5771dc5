// Filling texels no camera saw, by push-pull (Gortler et al., "The
// Lumigraph", 1996): weighted colours are averaged down an image pyramid and
// holes take the colour of the coarser level, blended up smoothly.
#pragma once

#include <opencv2/core.hpp>

namespace pmap::texture {

/// `acc` is CV_32FC4: (b, g, r) weighted sums and the weight sum. Returns
/// the BGR 8-bit image: acc / weight where weight > 0, the pushed-pulled
/// colour elsewhere; `fallback` (BGR 0..255) where nothing was seen at all.
cv::Mat resolveTexture(const cv::Mat& acc, const cv::Vec3f& fallback);

}  // namespace pmap::texture
