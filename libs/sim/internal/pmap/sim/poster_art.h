// Procedural poster images: deterministic from a seed, with structure (a
// stripe band, filled shapes, a title and lines of text-like word blocks, a
// frame), so that texture-quality tests can compare rendered or mapped
// textures against them.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>

namespace pmap::sim {

/// A BGR (CV_8UC3) poster image of the given size.
cv::Mat generatePosterImage(int width_px, int height_px, std::uint64_t seed);

}  // namespace pmap::sim
