#include "pmap/em/fine_triangles.h"

#include <algorithm>

namespace pmap::em {

std::vector<Triangle> fineTriangles(const std::vector<Eigen::Vector3d>& points,
                                    const Neighbours& neighbours,
                                    const std::vector<char>& is_outlier, double max_edge_m) {
  std::vector<Triangle> out;
  std::vector<char> used(points.size(), 0);
  const double max2 = max_edge_m * max_edge_m;
  std::vector<std::pair<double, std::int32_t>> cand;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!is_outlier[i] || used[i]) {
      continue;
    }
    cand.clear();
    auto consider = [&](std::int32_t q) {
      if (q < 0 || static_cast<std::size_t>(q) == i || !is_outlier[q] || used[q]) {
        return;
      }
      const double d2 = (points[q] - points[i]).squaredNorm();
      if (d2 <= max2 &&
          std::none_of(cand.begin(), cand.end(), [q](const auto& c) { return c.second == q; })) {
        cand.emplace_back(d2, q);
      }
    };
    for (const std::int32_t n : neighbours[i]) {
      consider(n);
      if (n >= 0) {
        for (const std::int32_t m : neighbours[static_cast<std::size_t>(n)]) {
          consider(m);
        }
      }
    }
    std::sort(cand.begin(), cand.end());
    // The closest pair that makes a proper triangle (not a sliver).
    bool made = false;
    for (std::size_t a = 0; a < cand.size() && !made; ++a) {
      for (std::size_t b = a + 1; b < cand.size() && !made; ++b) {
        const Eigen::Vector3d& p = points[i];
        const Eigen::Vector3d& q = points[cand[a].second];
        const Eigen::Vector3d& r = points[cand[b].second];
        if ((q - r).squaredNorm() > max2) {
          continue;
        }
        const double longest =
            std::max({(q - p).squaredNorm(), (r - p).squaredNorm(), (r - q).squaredNorm()});
        if (longest <= 0.0 || (q - p).cross(r - p).norm() < 0.1 * longest) {
          continue;
        }
        out.push_back({static_cast<std::int32_t>(i), cand[a].second, cand[b].second});
        used[i] = used[cand[a].second] = used[cand[b].second] = 1;
        made = true;
      }
    }
  }
  return out;
}

}  // namespace pmap::em
