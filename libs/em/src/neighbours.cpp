#include "pmap/em/neighbours.h"

#include <algorithm>
#include <unordered_map>

#include "pmap/em/point_grid.h"

namespace pmap::em {
Neighbours gridNeighbours(const std::vector<GridKey>& keys) {
  std::unordered_map<GridKey, std::int32_t, GridKeyHash> index;
  index.reserve(keys.size());
  for (size_t i = 0; i < keys.size(); ++i) {
    index.emplace(keys[i], static_cast<std::int32_t>(i));
  }
  auto find = [&](std::int32_t g, std::int32_t r, std::int32_t c) -> std::int32_t {
    const auto it = index.find(GridKey{g, r, c});
    return it == index.end() ? -1 : it->second;
  };
  Neighbours out(keys.size());
  for (size_t i = 0; i < keys.size(); ++i) {
    const GridKey& k = keys[i];
    out[i] = {find(k.group, k.row, k.col - 1), find(k.group, k.row, k.col + 1),
              find(k.group, k.row - 1, k.col), find(k.group, k.row + 1, k.col)};
  }
  return out;
}

Neighbours nearestNeighbours(const std::vector<Eigen::Vector3d>& points, double radius_m) {
  // Dense clouds (a range camera's frame: hundreds of points within the
  // radius) look within an eighth of it first: every point that close is
  // listed, so when four are, they are the four nearest (ties included).
  // Only points with fewer than four that close search the whole radius.
  const double near_m = 0.125 * radius_m;
  const PointGrid near_grid(points, near_m);
  const PointGrid grid(points, radius_m);
  Neighbours out(points.size(), {-1, -1, -1, -1});
  std::vector<std::pair<double, std::int32_t>> cand;
  const auto collect = [&](std::size_t i, const std::vector<std::int32_t>& found) {
    cand.clear();
    for (const std::int32_t j : found) {
      if (j != static_cast<std::int32_t>(i)) {
        cand.emplace_back((points[j] - points[i]).squaredNorm(), j);
      }
    }
  };
  for (size_t i = 0; i < points.size(); ++i) {
    collect(i, near_grid.within(points[i], near_m));
    if (cand.size() < 4) {
      collect(i, grid.within(points[i], radius_m));
    }
    const size_t k = std::min<size_t>(4, cand.size());
    std::partial_sort(cand.begin(), cand.begin() + static_cast<std::ptrdiff_t>(k), cand.end());
    for (size_t m = 0; m < k; ++m) {
      out[i][m] = cand[m].second;
    }
  }
  return out;
}

}  // namespace pmap::em
