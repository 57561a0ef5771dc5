#include "pmap/em/incremental_index.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pmap/em/cell_key.h"

namespace pmap::em {

void IncrementalIndex::remove(std::int32_t j) {
  const auto g = std::lower_bound(global_.begin(), global_.end(), j);
  if (g != global_.end() && *g == j) {
    global_.erase(g);
  }
  const auto it = keys_of_.find(j);
  if (it == keys_of_.end()) {
    return;
  }
  for (const std::int64_t k : it->second) {
    auto& list = cells_[k];
    list.erase(std::remove(list.begin(), list.end(), j), list.end());
    if (list.empty()) {
      cells_.erase(k);
    }
  }
  entries_ -= it->second.size();
  keys_of_.erase(it);
}

void IncrementalIndex::update(std::int32_t j, const Rectangle& rect) {
  remove(j);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const auto& c : rect.corners()) {
    lo = lo.cwiseMin(c);
    hi = hi.cwiseMax(c);
  }
  const Cell a = cellOf(lo - Eigen::Vector3d::Constant(inflate_));
  const Cell b = cellOf(hi + Eigen::Vector3d::Constant(inflate_));
  const double span = static_cast<double>(b.x() - a.x() + 1) *
                      static_cast<double>(b.y() - a.y() + 1) *
                      static_cast<double>(b.z() - a.z() + 1);
  if (!(span <= static_cast<double>(max_cells_)) ||
      static_cast<double>(entries_) + span > static_cast<double>(max_total_cells_)) {
    global_.insert(std::upper_bound(global_.begin(), global_.end(), j), j);
    return;
  }
  auto& keys = keys_of_[j];
  for (std::int64_t x = a.x(); x <= b.x(); ++x) {
    for (std::int64_t y = a.y(); y <= b.y(); ++y) {
      for (std::int64_t z = a.z(); z <= b.z(); ++z) {
        const std::int64_t k = cellKey(x, y, z);
        auto& list = cells_[k];
        const auto at = std::lower_bound(list.begin(), list.end(), j);
        if (at != list.end() && *at == j) {
          continue;  // far cells may share a key
        }
        list.insert(at, j);
        keys.push_back(k);
      }
    }
  }
  entries_ += keys.size();
}

void IncrementalIndex::candidates(const Eigen::Vector3d& p, std::vector<std::int32_t>& out) const {
  out.clear();
  const auto it = cells_.find(cellKeyOf(p, cell_));
  if (it != cells_.end()) {
    out = it->second;
  }
  if (!global_.empty()) {
    const auto middle = static_cast<std::ptrdiff_t>(out.size());
    out.insert(out.end(), global_.begin(), global_.end());
    std::inplace_merge(out.begin(), out.begin() + middle, out.end());
  }
}

}  // namespace pmap::em
