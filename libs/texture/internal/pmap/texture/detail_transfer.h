// How sharp a view is, measured where it matters: on the texels it colours,
// against the texture the other views give there.
//
// Both the view's samples S and the reference texture R are high-passed in
// texture space (minus their local mean, a Gaussian of sigma 1.5 texels,
// normalised convolution over the texels both have), and S's high-pass is
// regressed on R's: slope = sum hp(S) hp(R) / sum hp(R)^2. A blurred view
// keeps less of the fine detail than the consensus (slope well below 1), a
// sharp one as much or more. Sensor noise in S does not bias the slope (it
// is uncorrelated with R); content does not either, as both see the same
// texels. Unlike any whole-image blur measure, plain walls (noise only) give
// no slope instead of a wrong one.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "pmap/texture/blend.h"

namespace pmap::texture {

struct DetailSums {
  double sxy = 0;  ///< sum hp(S) hp(R)
  double syy = 0;  ///< sum hp(R)^2
  std::size_t texels = 0;
};

/// Sums over the visible tiles that have a reference (reference[tile] non-empty).
DetailSums measureDetail(const FrameView& view, const std::vector<TextureTile>& tiles,
                         const std::vector<VisibleTile>& visible,
                         const std::vector<cv::Mat>& reference, const TextureOptions& options);

/// The slope, when there was enough detail to tell (at least 500 texels with
/// a reference detail of 2 grey levels rms); empty otherwise.
std::optional<double> detailSlope(const DetailSums& sums);

}  // namespace pmap::texture
