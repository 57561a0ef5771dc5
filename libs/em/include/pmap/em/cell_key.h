// Cell coordinates and 64-bit cell keys for the EM's sparse grids (the point
// grid, the rectangle indices, the split tests' grids). Any double maps to a
// cell without overflow: coordinates are clamped to +-2^52 cells (NaN to 0),
// so a point 1e12 m away costs one cell like any other, never a dense array
// over the distance.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace pmap::em {

/// Largest cell coordinate magnitude (2^52: exact in a double, and sums or
/// differences of two coordinates stay far from int64 overflow).
constexpr std::int64_t kMaxCellCoord = std::int64_t{1} << 52;

/// floor(x) as a cell coordinate, clamped to [-kMaxCellCoord, kMaxCellCoord];
/// NaN gives 0.
inline std::int64_t cellCoord(double x) {
  constexpr double kMax = static_cast<double>(kMaxCellCoord);
  if (std::isnan(x)) {
    return 0;
  }
  return static_cast<std::int64_t>(std::floor(std::clamp(x, -kMax, kMax)));
}

/// ceil(x) clamped to [0, kMaxCellCoord] (NaN gives 0): the number of cells
/// spanning `x` cell lengths.
inline std::int64_t ceilCells(double x) {
  constexpr double kMax = static_cast<double>(kMaxCellCoord);
  if (!(x > 0.0)) {
    return 0;
  }
  return static_cast<std::int64_t>(std::ceil(std::min(x, kMax)));
}

/// Number of cells (at least 1) of a side `length_cells` cell lengths long.
inline std::int64_t cellCount(double length_cells) {
  return std::max<std::int64_t>(1, ceilCells(length_cells));
}

/// Cell index of offset `x_cells` on a line of `n` cells: truncated and
/// clamped to [0, n - 1] (NaN gives 0).
inline std::int64_t clampedCell(double x_cells, std::int64_t n) {
  if (!(x_cells >= 0.0)) {
    return 0;
  }
  if (x_cells >= static_cast<double>(n - 1)) {
    return n - 1;
  }
  return static_cast<std::int64_t>(x_cells);
}

/// The cell of `p` on a grid of `cell_m`: cellCoord of each coordinate
/// (the common case, every coordinate within range, in one vector step).
inline Eigen::Matrix<std::int64_t, 3, 1> cellOf(const Eigen::Vector3d& p, double cell_m) {
  const Eigen::Array3d f = (p / cell_m).array().floor();
  if ((f.abs() < static_cast<double>(kMaxCellCoord)).all()) {  // false for NaN
    return f.cast<std::int64_t>().matrix();
  }
  return {cellCoord(p.x() / cell_m), cellCoord(p.y() / cell_m), cellCoord(p.z() / cell_m)};
}

/// A 64-bit key of cell (x, y, z). Cells within +-2^20 of the origin (100 km
/// at 0.1 m cells) pack exactly into 21 bits per axis; farther cells are
/// hashed into keys with the top bit set, so two far cells may share a key
/// (users treat a cell's list as candidates and check distances).
inline std::int64_t cellKey(std::int64_t x, std::int64_t y, std::int64_t z) {
  constexpr std::int64_t kHalf = std::int64_t{1} << 20;
  constexpr std::int64_t kMask = (std::int64_t{1} << 21) - 1;
  if (x >= -kHalf && x < kHalf && y >= -kHalf && y < kHalf && z >= -kHalf && z < kHalf) {
    return ((x & kMask) << 42) | ((y & kMask) << 21) | (z & kMask);
  }
  constexpr std::uint64_t kMul = 0x9E3779B97F4A7C15ull;
  std::uint64_t h = static_cast<std::uint64_t>(x) * kMul;
  h = (h ^ (h >> 29) ^ static_cast<std::uint64_t>(y)) * kMul;
  h = (h ^ (h >> 29) ^ static_cast<std::uint64_t>(z)) * kMul;
  h ^= h >> 32;
  return static_cast<std::int64_t>(h | (std::uint64_t{1} << 63));
}

/// cellKey(cellOf(p, cell_m)), with the common case (every coordinate
/// within +-2^20 cells) in a few vector steps: the hot path of the indices.
inline std::int64_t cellKeyOf(const Eigen::Vector3d& p, double cell_m) {
  const double x = std::floor(p.x() / cell_m);
  const double y = std::floor(p.y() / cell_m);
  const double z = std::floor(p.z() / cell_m);
  constexpr double kHalf = 1048576.0;  // 2^20; every comparison is false for NaN
  if (x >= -kHalf && x < kHalf && y >= -kHalf && y < kHalf && z >= -kHalf && z < kHalf) {
    constexpr std::int64_t kMask = (std::int64_t{1} << 21) - 1;
    return ((static_cast<std::int64_t>(x) & kMask) << 42) |
           ((static_cast<std::int64_t>(y) & kMask) << 21) | (static_cast<std::int64_t>(z) & kMask);
  }
  const Eigen::Matrix<std::int64_t, 3, 1> c = cellOf(p, cell_m);
  return cellKey(c.x(), c.y(), c.z());
}

}  // namespace pmap::em
