#include "pmap/em/point_grid.h"

#include <algorithm>
#include <cmath>

#include "pmap/em/cell_key.h"

namespace pmap::em {

PointGrid::PointGrid(const std::vector<Eigen::Vector3d>& points, double cell_m)
    : points_(points), cell_(cell_m) {
  for (size_t i = 0; i < points.size(); ++i) {
    cells_[cellKeyOf(points[i], cell_)].push_back(static_cast<std::int32_t>(i));
  }
}

std::vector<std::int32_t> PointGrid::inBox(const Eigen::Vector3d& lo,
                                           const Eigen::Vector3d& hi) const {
  const Cell a = cellOf(lo);
  const Cell b = cellOf(hi);
  std::vector<std::int32_t> out;
  const double cells = static_cast<double>(b.x() - a.x() + 1) *
                       static_cast<double>(b.y() - a.y() + 1) *
                       static_cast<double>(b.z() - a.z() + 1);
  if (cells > 4.0 * static_cast<double>(cells_.size())) {  // huge box: scan the occupied cells
    for (const auto& [k, v] : cells_) {
      out.insert(out.end(), v.begin(), v.end());
    }
  } else {
    for (std::int64_t x = a.x(); x <= b.x(); ++x) {
      for (std::int64_t y = a.y(); y <= b.y(); ++y) {
        for (std::int64_t z = a.z(); z <= b.z(); ++z) {
          const auto it = cells_.find(cellKey(x, y, z));
          if (it != cells_.end()) {
            out.insert(out.end(), it->second.begin(), it->second.end());
          }
        }
      }
    }
  }
  std::sort(out.begin(), out.end());
  // Far cells hashed to one key (cell_key.h) would list their points twice.
  out.erase(std::unique(out.begin(), out.end()), out.end());
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
