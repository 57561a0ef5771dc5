#include "pmap/em/subsample.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace pmap::em {
namespace {

// Median distance from a point to its nearest listed neighbour, over up to
// 1,000 evenly spaced points (0 if none has a neighbour).
double medianNeighbourDistance(const std::vector<Eigen::Vector3d>& points,
                               const Neighbours& neighbours) {
  const std::size_t step = std::max<std::size_t>(1, points.size() / 1000);
  std::vector<double> d;
  for (std::size_t i = 0; i < points.size(); i += step) {
    double best = std::numeric_limits<double>::infinity();
    for (const std::int32_t n : neighbours[i]) {
      if (n >= 0) {
        best = std::min(best, (points[static_cast<std::size_t>(n)] - points[i]).norm());
      }
    }
    if (std::isfinite(best) && best > 0.0) {
      d.push_back(best);
    }
  }
  if (d.empty()) {
    return 0.0;
  }
  std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
  return d[d.size() / 2];
}

}  // namespace

Subsample drawSubsample(const std::vector<Eigen::Vector3d>& points, const Neighbours& neighbours,
                        const std::vector<std::int32_t>& rows, std::size_t target,
                        std::uint64_t seed) {
  Subsample s;
  const std::size_t n = points.size();
  target = std::min(target, n);
  // Selection sampling (Knuth's algorithm S): each point is kept with the
  // probability that leaves exactly `target`, in one pass, in input order.
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  s.index.reserve(target);
  for (std::size_t i = 0; i < n && s.index.size() < target; ++i) {
    const double needed = static_cast<double>(target - s.index.size());
    if (static_cast<double>(n - i) * uniform(rng) < needed) {
      s.index.push_back(static_cast<std::int32_t>(i));
    }
  }
  s.points.reserve(s.index.size());
  for (const std::int32_t i : s.index) {
    s.points.push_back(points[static_cast<std::size_t>(i)]);
    if (!rows.empty()) {
      s.rows.push_back(rows[static_cast<std::size_t>(i)]);
    }
  }
  s.fraction = n == 0 ? 1.0 : static_cast<double>(s.index.size()) / static_cast<double>(n);
  const double spacing = medianNeighbourDistance(points, neighbours);
  if (spacing > 0.0 && s.fraction > 0.0) {
    s.neighbours = nearestNeighbours(s.points, 2.5 * spacing / std::sqrt(s.fraction));
  } else {
    s.neighbours.assign(s.points.size(), {-1, -1, -1, -1});
  }
  return s;
}

PlanarEmOptions scaledToSample(const PlanarEmOptions& o, double fraction) {
  PlanarEmOptions s = o;
  s.kappa = o.kappa * fraction;
  s.min_gain = o.min_gain * fraction;
  s.empty_area_cost = o.empty_area_cost * fraction;
  s.convergence_absolute_nats = o.convergence_absolute_nats * fraction;
  s.min_support =
      std::max(o.rules.min_part_points, static_cast<int>(std::ceil(o.min_support * fraction)));
  s.coarse_points = 0;
  return s;
}

}  // namespace pmap::em
