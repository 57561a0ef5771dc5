// Which measurements are adjacent, for seeding new surfaces from "three
// adjacent poorly explained measurements" (section IV-C) and for fine
// triangles: neighbours in beam and scan order for scanners, nearest
// neighbours for unorganised clouds.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace pmap::em {

/// Up to four neighbours per point, -1 where there is none. For grids:
/// {previous column, next column, previous row, next row}.
using Neighbours = std::vector<std::array<std::int32_t, 4>>;

/// A point's place in a measurement grid: for a 2D scanner, group = sensor,
/// row = scan rank, col = beam; for a range image, group = frame, row and
/// col = pixel.
struct GridKey {
  std::int32_t group = 0;
  std::int32_t row = 0;
  std::int32_t col = 0;
  bool operator==(const GridKey& o) const {
    return group == o.group && row == o.row && col == o.col;
  }
};

/// Hash of a GridKey (all 96 bits take part).
struct GridKeyHash {
  std::size_t operator()(const GridKey& k) const noexcept {
    std::uint64_t h = static_cast<std::uint32_t>(k.group);
    h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint32_t>(k.row);
    h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint32_t>(k.col);
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

/// Neighbours on the same group at row +-1 or col +-1 (duplicate keys: the
/// first point wins).
Neighbours gridNeighbours(const std::vector<GridKey>& keys);

/// The (up to) four nearest other points within `radius_m`, for clouds
/// without grid structure. Deterministic (ties by index), whatever the
/// number of `threads` (>= 1) answering.
Neighbours nearestNeighbours(const std::vector<Eigen::Vector3d>& points, double radius_m,
                             int threads = 1);

}  // namespace pmap::em
