// Test support: a minimal binary glTF 2.0 (GLB) of flat quads, so the viewer
// tests need no exporter. Like planar-mapper's exporter, vertices are in the
// world frame (z up) under a root node that turns z up into glTF's y up.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <random>
#include <vector>

namespace pmap::viewer::testing {

struct TestQuad {
  std::array<Eigen::Vector3f, 4> corners;   ///< counter-clockwise seen from the normal
  Eigen::Vector3f color{0.8f, 0.8f, 0.8f};  ///< RGB in [0, 1]
  bool textured = false;                    ///< a checkerboard PNG instead of the colour
};

/// A GLB of `quads`: one primitive (two triangles) per quad, double-sided.
std::vector<std::uint8_t> makeQuadsGlb(const std::vector<TestQuad>& quads);

/// A corridor along x (floor and two walls, no ceiling), `segments` quads of
/// 2 m per side, 2 m wide and 2.5 m high; every fourth quad textured.
std::vector<TestQuad> corridorQuads(int segments);

/// `count` points on the quads with 1 cm noise, from `seed`.
std::vector<Eigen::Vector3f> pointsOnQuads(const std::vector<TestQuad>& quads, std::size_t count,
                                           std::uint32_t seed);

}  // namespace pmap::viewer::testing
