#include "pmap/em/rectangle_index.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "pmap/em/cell_key.h"

namespace pmap::em {

RectangleIndex::RectangleIndex(const std::vector<Surface>& surfaces, double inflate_m,
                               double cell_m, std::size_t max_cells, std::size_t max_total_cells)
    : cell_(cell_m) {
  // Each bounded rectangle's inflated bounding box in cells; the smallest
  // are indexed first, so a budget overrun sends the largest to global_.
  std::vector<std::tuple<double, std::int32_t, Cell, Cell>> boxes;  // cells, surface, a, b
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
    const Cell a = cellOf(lo - Eigen::Vector3d::Constant(inflate_m));
    const Cell b = cellOf(hi + Eigen::Vector3d::Constant(inflate_m));
    const double span = static_cast<double>(b.x() - a.x() + 1) *
                        static_cast<double>(b.y() - a.y() + 1) *
                        static_cast<double>(b.z() - a.z() + 1);
    if (!(span <= static_cast<double>(max_cells))) {
      global_.push_back(idx);
      continue;
    }
    boxes.emplace_back(span, idx, a, b);
  }
  std::sort(boxes.begin(), boxes.end(), [](const auto& x, const auto& y) {
    return std::get<0>(x) < std::get<0>(y) ||
           (std::get<0>(x) == std::get<0>(y) && std::get<1>(x) < std::get<1>(y));
  });
  std::vector<std::tuple<std::int32_t, Cell, Cell>> indexed;
  for (const auto& [span, idx, a, b] : boxes) {
    if (static_cast<double>(entries_) + span > static_cast<double>(max_total_cells)) {
      global_.push_back(idx);
      continue;
    }
    entries_ += static_cast<std::size_t>(span);
    indexed.emplace_back(idx, a, b);
  }
  std::sort(global_.begin(), global_.end());
  // Surfaces in index order: each cell's list ascending.
  std::sort(indexed.begin(), indexed.end(),
            [](const auto& x, const auto& y) { return std::get<0>(x) < std::get<0>(y); });
  for (const auto& [idx, a, b] : indexed) {
    for (std::int64_t x = a.x(); x <= b.x(); ++x) {
      for (std::int64_t y = a.y(); y <= b.y(); ++y) {
        for (std::int64_t z = a.z(); z <= b.z(); ++z) {
          auto& list = cells_[cellKey(x, y, z)];
          if (list.empty() || list.back() != idx) {  // far cells may share a key
            list.push_back(idx);
          }
        }
      }
    }
  }
}

const std::vector<std::int32_t>* RectangleIndex::candidatesRef(
    const Eigen::Vector3d& p, std::vector<std::int32_t>& scratch) const {
  if (!global_.empty()) {
    candidates(p, scratch);
    return &scratch;
  }
  const auto it = cells_.find(cellKeyOf(p, cell_));
  return it == cells_.end() ? nullptr : &it->second;
}

void RectangleIndex::candidates(const Eigen::Vector3d& p, std::vector<std::int32_t>& out) const {
  out.clear();
  const auto it = cells_.find(cellKeyOf(p, cell_));
  if (it != cells_.end()) {
    out = it->second;
  }
  if (!global_.empty()) {
    out.insert(out.end(), global_.begin(), global_.end());
    std::sort(out.begin(), out.end());
  }
}

}  // namespace pmap::em
