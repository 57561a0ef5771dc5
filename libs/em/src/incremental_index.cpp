#include "pmap/em/incremental_index.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pmap::em {

std::int64_t IncrementalIndex::key(int x, int y, int z) const {
  constexpr std::int64_t kMask = (1 << 21) - 1;
  return ((static_cast<std::int64_t>(x) & kMask) << 42) |
         ((static_cast<std::int64_t>(y) & kMask) << 21) | (static_cast<std::int64_t>(z) & kMask);
}

void IncrementalIndex::remove(std::int32_t j) {
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
  const Eigen::Vector3i a = ((lo.array() - inflate_) / cell_).floor().cast<int>();
  const Eigen::Vector3i b = ((hi.array() + inflate_) / cell_).floor().cast<int>();
  auto& keys = keys_of_[j];
  for (int x = a.x(); x <= b.x(); ++x) {
    for (int y = a.y(); y <= b.y(); ++y) {
      for (int z = a.z(); z <= b.z(); ++z) {
        const std::int64_t k = key(x, y, z);
        auto& list = cells_[k];
        list.insert(std::upper_bound(list.begin(), list.end(), j), j);
        keys.push_back(k);
      }
    }
  }
}

void IncrementalIndex::candidates(const Eigen::Vector3d& p, std::vector<std::int32_t>& out) const {
  out.clear();
  const Eigen::Vector3i c = (p / cell_).array().floor().cast<int>();
  const auto it = cells_.find(key(c.x(), c.y(), c.z()));
  if (it != cells_.end()) {
    out = it->second;
  }
}

}  // namespace pmap::em
