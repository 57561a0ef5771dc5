#include "pmap/em/rectangle_index.h"

#include <algorithm>
#include <cmath>

namespace pmap::em {

RectangleIndex::RectangleIndex(const std::vector<Surface>& surfaces, double inflate_m,
                               double cell_m, std::size_t max_cells)
    : cell_(cell_m) {
  for (size_t j = 0; j < surfaces.size(); ++j) {
    const Rectangle& r = surfaces[j].rect;
    const auto idx = static_cast<std::int32_t>(j);
    if (!r.bounded) {
      global_.push_back(idx);
      continue;
    }
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d hi = -lo;
    for (const auto& c : r.corners()) {
      lo = lo.cwiseMin(c);
      hi = hi.cwiseMax(c);
    }
    const Eigen::Vector3i a = cellOf(lo - Eigen::Vector3d::Constant(inflate_m));
    const Eigen::Vector3i b = cellOf(hi + Eigen::Vector3d::Constant(inflate_m));
    const Eigen::Vector3d span = (b - a).cast<double>() + Eigen::Vector3d::Ones();
    if (span.prod() > static_cast<double>(max_cells)) {
      global_.push_back(idx);
      continue;
    }
    for (int x = a.x(); x <= b.x(); ++x) {
      for (int y = a.y(); y <= b.y(); ++y) {
        for (int z = a.z(); z <= b.z(); ++z) {
          cells_[key({x, y, z})].push_back(idx);
        }
      }
    }
  }
}

std::int64_t RectangleIndex::key(const Eigen::Vector3i& c) const {
  constexpr std::int64_t kMask = (1 << 21) - 1;
  return ((static_cast<std::int64_t>(c.x()) & kMask) << 42) |
         ((static_cast<std::int64_t>(c.y()) & kMask) << 21) |
         (static_cast<std::int64_t>(c.z()) & kMask);
}

Eigen::Vector3i RectangleIndex::cellOf(const Eigen::Vector3d& p) const {
  return (p / cell_).array().floor().cast<int>();
}

const std::vector<std::int32_t>* RectangleIndex::candidatesRef(
    const Eigen::Vector3d& p, std::vector<std::int32_t>& scratch) const {
  if (!global_.empty()) {
    candidates(p, scratch);
    return &scratch;
  }
  const auto it = cells_.find(key(cellOf(p)));
  return it == cells_.end() ? nullptr : &it->second;
}

void RectangleIndex::candidates(const Eigen::Vector3d& p, std::vector<std::int32_t>& out) const {
  out.clear();
  const auto it = cells_.find(key(cellOf(p)));
  if (it != cells_.end()) {
    out = it->second;
  }
  if (!global_.empty()) {
    out.insert(out.end(), global_.begin(), global_.end());
    std::sort(out.begin(), out.end());
  }
}

}  // namespace pmap::em
