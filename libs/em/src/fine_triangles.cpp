#include "pmap/em/fine_triangles.h"

#include <algorithm>
#include <map>
#include <optional>
#include <utility>

#include "pmap/em/cell_key.h"
#include "pmap/em/point_grid.h"

namespace pmap::em {
namespace {

/// Candidates (squared distance to the anchor, point index), nearest first.
using Candidates = std::vector<std::pair<double, std::int32_t>>;

/// p, q, r make a proper triangle: every edge <= sqrt(max2) (the anchor's
/// own edges are checked by whoever listed q and r) and an area that is not
/// a sliver's (twice the area >= 0.1 x the longest edge squared).
bool properTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& r,
                    double max2) {
  if ((q - r).squaredNorm() > max2) {
    return false;
  }
  const double longest =
      std::max({(q - p).squaredNorm(), (r - p).squaredNorm(), (r - q).squaredNorm()});
  return longest > 0.0 && (q - p).cross(r - p).norm() >= 0.1 * longest;
}

/// The closest pair of `cand` (sorted) that makes a proper triangle with
/// point `anchor`, if any.
std::optional<Triangle> closestProperTriangle(const std::vector<Eigen::Vector3d>& points,
                                              std::int32_t anchor, const Candidates& cand,
                                              double max2) {
  for (std::size_t a = 0; a < cand.size(); ++a) {
    for (std::size_t b = a + 1; b < cand.size(); ++b) {
      if (properTriangle(points[anchor], points[cand[a].second], points[cand[b].second], max2)) {
        return Triangle{anchor, cand[a].second, cand[b].second};
      }
    }
  }
  return std::nullopt;
}

/// Takes `t` when present: appends it and marks its corners used.
bool take(const std::optional<Triangle>& t, std::vector<Triangle>& out, std::vector<char>& used) {
  if (!t) {
    return false;
  }
  out.push_back(*t);
  for (const std::int32_t v : *t) {
    used[static_cast<std::size_t>(v)] = 1;
  }
  return true;
}

/// The paper's grouping: neighbours one or two hops away in the graph.
std::vector<Triangle> graphTriangles(const std::vector<Eigen::Vector3d>& points,
                                     const Neighbours& neighbours,
                                     const std::vector<char>& is_outlier, double max2) {
  std::vector<Triangle> out;
  std::vector<char> used(points.size(), 0);
  Candidates cand;
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
    take(closestProperTriangle(points, static_cast<std::int32_t>(i), cand, max2), out, used);
  }
  return out;
}

/// Grouping of the cube representatives: unused ones within the longest
/// edge in space, in cube order.
std::vector<Triangle> cubeTriangles(const std::vector<Eigen::Vector3d>& points,
                                    const std::vector<char>& is_outlier, double max_edge_m,
                                    double cell_m) {
  const std::vector<std::int32_t> reps = cubeRepresentatives(points, is_outlier, cell_m);
  std::vector<Eigen::Vector3d> at(reps.size());
  for (std::size_t k = 0; k < reps.size(); ++k) {
    at[k] = points[static_cast<std::size_t>(reps[k])];
  }
  const PointGrid grid(at, max_edge_m);
  const double max2 = max_edge_m * max_edge_m;
  std::vector<Triangle> out;
  std::vector<char> used(points.size(), 0);
  Candidates cand;
  for (std::size_t k = 0; k < reps.size(); ++k) {
    const std::int32_t i = reps[k];
    if (used[static_cast<std::size_t>(i)]) {
      continue;
    }
    cand.clear();
    for (const std::int32_t n : grid.within(at[k], max_edge_m)) {
      const std::int32_t q = reps[static_cast<std::size_t>(n)];
      if (q != i && !used[static_cast<std::size_t>(q)]) {
        cand.emplace_back((at[static_cast<std::size_t>(n)] - at[k]).squaredNorm(), q);
      }
    }
    std::sort(cand.begin(), cand.end());
    take(closestProperTriangle(points, i, cand, max2), out, used);
  }
  return out;
}

}  // namespace

std::vector<std::int32_t> cubeRepresentatives(const std::vector<Eigen::Vector3d>& points,
                                              const std::vector<char>& is_outlier, double cell_m) {
  // Exact cube coordinates as the key (not cellKey, whose far cells may
  // share a key): the map's order is the cubes' lexicographic order.
  using Cube = std::array<std::int64_t, 3>;
  struct Members {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    std::vector<std::int32_t> points;
  };
  std::map<Cube, Members> cubes;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!is_outlier[i] || !points[i].allFinite()) {
      continue;
    }
    const Eigen::Matrix<std::int64_t, 3, 1> c = cellOf(points[i], cell_m);
    Members& m = cubes[Cube{c.x(), c.y(), c.z()}];
    m.sum += points[i];
    m.points.push_back(static_cast<std::int32_t>(i));
  }
  std::vector<std::int32_t> reps;
  reps.reserve(cubes.size());
  for (const auto& [cube, m] : cubes) {
    const Eigen::Vector3d mean = m.sum / static_cast<double>(m.points.size());
    std::int32_t best = m.points.front();  // members ascend, so ties keep the lowest
    double best2 = (points[static_cast<std::size_t>(best)] - mean).squaredNorm();
    for (const std::int32_t i : m.points) {
      const double d2 = (points[static_cast<std::size_t>(i)] - mean).squaredNorm();
      if (d2 < best2) {
        best = i;
        best2 = d2;
      }
    }
    reps.push_back(best);
  }
  return reps;
}

std::vector<Triangle> fineTriangles(const std::vector<Eigen::Vector3d>& points,
                                    const Neighbours& neighbours,
                                    const std::vector<char>& is_outlier, double max_edge_m,
                                    double cell_m) {
  if (cell_m > 0.0) {
    return cubeTriangles(points, is_outlier, max_edge_m, cell_m);
  }
  return graphTriangles(points, neighbours, is_outlier, max_edge_m * max_edge_m);
}

}  // namespace pmap::em
