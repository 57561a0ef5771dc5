// A hashed uniform grid over fixed points, for radius queries. Only occupied
// cells are stored (64-bit keys, cell_key.h): memory follows the points
// whatever their extent.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "pmap/em/cell_key.h"

namespace pmap::em {

class PointGrid {
 public:
  PointGrid(const std::vector<Eigen::Vector3d>& points, double cell_m);

  /// Indices of the points within `radius_m` of `centre`, ascending.
  std::vector<std::int32_t> within(const Eigen::Vector3d& centre, double radius_m) const;
  /// Indices of the points in cells overlapping the box [lo, hi], ascending
  /// (a superset of the points inside the box).
  std::vector<std::int32_t> inBox(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) const;

  double cell() const { return cell_; }
  /// Number of occupied cells (at most the number of points).
  std::size_t occupiedCells() const { return cells_.size(); }

 private:
  using Cell = Eigen::Matrix<std::int64_t, 3, 1>;
  Cell cellOf(const Eigen::Vector3d& p) const { return em::cellOf(p, cell_); }

  const std::vector<Eigen::Vector3d>& points_;
  double cell_;
  std::unordered_map<std::int64_t, std::vector<std::int32_t>> cells_;
};

}  // namespace pmap::em
