// A hashed uniform grid over fixed points, for radius queries.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <unordered_map>
#include <vector>

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

 private:
  std::int64_t key(std::int64_t x, std::int64_t y, std::int64_t z) const;
  Eigen::Vector3i cellOf(const Eigen::Vector3d& p) const;

  const std::vector<Eigen::Vector3d>& points_;
  double cell_;
  std::unordered_map<std::int64_t, std::vector<std::int32_t>> cells_;
};

}  // namespace pmap::em
