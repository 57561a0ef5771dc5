// Deterministic subsampling of the raw points embedded in viewer.html.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pmap::viewer {

/// The finite points of `points`, every k-th one in input order, with the
/// smallest stride k >= 1 that keeps at most `max_points` (0: none). The
/// same input always gives the same output.
std::vector<Eigen::Vector3f> subsamplePoints(const std::vector<Eigen::Vector3f>& points,
                                             std::size_t max_points);

/// Little-endian float32 x y z triples of `points`, as a JS Float32Array reads them.
std::vector<std::uint8_t> packFloat32(const std::vector<Eigen::Vector3f>& points);

}  // namespace pmap::viewer
