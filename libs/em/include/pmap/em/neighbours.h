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
};

/// Neighbours on the same group at row +-1 or col +-1 (duplicate keys: the
/// first point wins).
Neighbours gridNeighbours(const std::vector<GridKey>& keys);

/// The (up to) four nearest other points within `radius_m`, for clouds
/// without grid structure. Deterministic (ties by index).
Neighbours nearestNeighbours(const std::vector<Eigen::Vector3d>& points, double radius_m);

}  // namespace pmap::em
