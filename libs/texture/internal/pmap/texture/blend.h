// Accumulating views into tile textures: every tile keeps a CV_32FC4 image
// of (b, g, r, weight). "weighted" sums w * colour and w; "best" keeps w *
// colour and w of the single best-weighted view.
#pragma once

#include <cstddef>
#include <functional>
#include <opencv2/core.hpp>
#include <vector>

#include "pmap/texture/view_geometry.h"
#include "pmap/texture/view_sampler.h"

namespace pmap::texture {

struct VisibleTile {
  std::size_t tile = 0;
  TexelBox box;
};

/// Tiles (with their texel boxes) that `frame` may see.
std::vector<VisibleTile> visibleTiles(const std::vector<TextureTile>& tiles,
                                      const CameraFrame& frame, double max_distance_m);

/// Adds `view` to the accumulators of the visible tiles that have one
/// (acc[tile] non-empty). Tiles are spread over `threads` threads; each tile
/// is written by one thread, so the result does not depend on the count.
/// Returns the number of texels the view coloured.
std::size_t accumulateView(const FrameView& view, const std::vector<TextureTile>& tiles,

                           const std::vector<VisibleTile>& visible, const TextureOptions& options,
                           std::vector<cv::Mat>& acc);

/// Calls fn(i) for i in [0, n) on up to `threads` threads.
void parallelFor(std::size_t n, int threads, const std::function<void(std::size_t)>& fn);

}  // namespace pmap::texture
