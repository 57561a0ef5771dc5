#include "pmap/em/point_grid.h"

#include <algorithm>
#include <cmath>

namespace pmap::em {

PointGrid::PointGrid(const std::vector<Eigen::Vector3d>& points, double cell_m)
    : points_(points), cell_(cell_m) {
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3i c = cellOf(points[i]);
    cells_[key(c.x(), c.y(), c.z())].push_back(static_cast<std::int32_t>(i));
  }
}

std::int64_t PointGrid::key(std::int64_t x, std::int64_t y, std::int64_t z) const {
  // 21 bits per axis: +-1e6 cells, +-100 km at 0.1 m cells.
  constexpr std::int64_t kMask = (1 << 21) - 1;
  return ((x & kMask) << 42) | ((y & kMask) << 21) | (z & kMask);
}

Eigen::Vector3i PointGrid::cellOf(const Eigen::Vector3d& p) const {
  return (p / cell_).array().floor().cast<int>();
}

std::vector<std::int32_t> PointGrid::inBox(const Eigen::Vector3d& lo,
                                           const Eigen::Vector3d& hi) const {
  const Eigen::Vector3i a = cellOf(lo);
  const Eigen::Vector3i b = cellOf(hi);
  std::vector<std::int32_t> out;
  const double cells =
      static_cast<double>(b.x() - a.x() + 1) * (b.y() - a.y() + 1) * (b.z() - a.z() + 1);
  if (cells > 4.0 * static_cast<double>(cells_.size())) {  // huge box: scan the occupied cells
    for (const auto& [k, v] : cells_) {
      out.insert(out.end(), v.begin(), v.end());
    }
  } else {
    for (int x = a.x(); x <= b.x(); ++x) {
      for (int y = a.y(); y <= b.y(); ++y) {
        for (int z = a.z(); z <= b.z(); ++z) {
          const auto it = cells_.find(key(x, y, z));
          if (it != cells_.end()) {
            out.insert(out.end(), it->second.begin(), it->second.end());
          }
        }
      }
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::int32_t> PointGrid::within(const Eigen::Vector3d& centre, double radius_m) const {
  const Eigen::Vector3d r = Eigen::Vector3d::Constant(radius_m);
  std::vector<std::int32_t> out = inBox(centre - r, centre + r);
  const double r2 = radius_m * radius_m;
  out.erase(
      std::remove_if(out.begin(), out.end(),
                     [&](std::int32_t i) { return (points_[i] - centre).squaredNorm() > r2; }),
      out.end());
  return out;
}

}  // namespace pmap::em
