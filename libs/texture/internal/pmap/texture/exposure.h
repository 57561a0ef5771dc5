// Exposure compensation: one gain per camera frame so that overlapping views
// agree. Works on thumbnails and coarse tiles: each round builds, for every
// frame, the reference the other frames give (the blended texture without the
// frame's own contribution) and takes the median of reference / sample
// luminance over the texels both see (robust to occlusions the map misses).
// Gains are normalised to a median of 1 over the frames that overlap others.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "pmap/texture/camera_frame.h"
#include "pmap/texture/texture_options.h"
#include "pmap/texture/texture_tile.h"

namespace pmap::texture {

struct ExposureResult {
  std::vector<float> gains;  ///< per frame; 1 for frames without overlap
  int rounds = 0;
  std::size_t frames_with_overlap = 0;
};

/// `frames[i]` describes `images[i]` (BGR 8-bit; empty: frame unused);
/// `frame_weights[i]` its blur factor.
ExposureResult estimateGains(const std::vector<TextureTile>& tiles,
                             const std::vector<CameraFrame>& frames,
                             const std::vector<cv::Mat>& images,
                             const std::vector<double>& frame_weights,
                             const TextureOptions& options);

}  // namespace pmap::texture
