#include "pmap/em/model_selection.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>

#include "pmap/em/cell_key.h"

namespace pmap::em {

double emptyArea(const std::vector<Eigen::Vector3d>& points,
                 const std::vector<std::int32_t>& members, const Rectangle& rect, double cell_m) {
  if (!rect.bounded) {
    return 0.0;
  }
  const Eigen::Vector3d v = rect.axisV();
  // A dense occupancy grid over the rectangle; for huge ones (a rectangle
  // stretched by a stray point) the distinct cells of the members, so memory
  // follows the members, not the extent. Members beyond the boundary count
  // in the border cells.
  const std::int64_t cols = ceilCells(2.0 * rect.half_u / cell_m) + 1;
  const std::int64_t rows = ceilCells(2.0 * rect.half_v / cell_m) + 1;
  const bool use_dense = static_cast<double>(cols) * static_cast<double>(rows) <= 4000000.0;
  std::vector<char> dense(use_dense ? static_cast<std::size_t>(cols * rows) : 0, 0);
  std::vector<std::pair<std::int64_t, std::int64_t>> sparse;
  std::size_t covered_cells = 0;
  for (const std::int32_t i : members) {
    const Eigen::Vector3d d = points[static_cast<std::size_t>(i)] - rect.centre;
    const std::int64_t a = clampedCell((rect.axis_u.dot(d) + rect.half_u) / cell_m, cols);
    const std::int64_t b = clampedCell((v.dot(d) + rect.half_v) / cell_m, rows);
    if (use_dense) {
      char& c = dense[static_cast<std::size_t>(b * cols + a)];
      covered_cells += c == 0 ? 1 : 0;
      c = 1;
    } else {
      sparse.emplace_back(b, a);
    }
  }
  if (!use_dense) {
    std::sort(sparse.begin(), sparse.end());
    covered_cells =
        static_cast<std::size_t>(std::unique(sparse.begin(), sparse.end()) - sparse.begin());
  }
  const double covered = static_cast<double>(covered_cells) * cell_m * cell_m;
  return std::max(0.0, rect.area() - covered);
}

double logPosterior(const Responsibilities& resp, const std::vector<Surface>& surfaces,
                    const std::vector<double>& empty_areas, const PlanarEmOptions& options) {
  double empty = 0.0;
  for (const double a : empty_areas) {
    empty += a;
  }
  return resp.total_loglik - options.kappa * static_cast<double>(surfaces.size()) -
         options.empty_area_cost * empty;
}

double combineScores(double a, double b, PlanarEmOptions::Scoring scoring) {
  return scoring == PlanarEmOptions::Scoring::kSoft ? logAddExp(a, b) : std::max(a, b);
}

double pointScore(const Responsibilities& resp, std::size_t i, double s_star,
                  PlanarEmOptions::Scoring scoring, std::int64_t skip_entry) {
  double l = s_star;
  for (std::uint32_t k = resp.offsets[i]; k < resp.offsets[i + 1]; ++k) {
    if (static_cast<std::int64_t>(k) != skip_entry) {
      l = combineScores(l, resp.score[k], scoring);
    }
  }
  return l;
}

double logLikelihoodChange(const std::vector<Eigen::Vector3d>& points, const Responsibilities& resp,
                           const MeasurementModel& model, const std::vector<std::int32_t>& affected,
                           const std::vector<std::int32_t>& removed,
                           const std::vector<Rectangle>& added, double tolerance,
                           PlanarEmOptions::Scoring scoring) {
  const double s_star = model.outlierScore();
  const double min_score = s_star + std::log(tolerance);
  double change = 0.0;
  for (const std::int32_t i : affected) {
    const auto p = static_cast<std::size_t>(i);
    double l = s_star;
    for (std::uint32_t k = resp.offsets[p]; k < resp.offsets[p + 1]; ++k) {
      if (std::find(removed.begin(), removed.end(), resp.surface[k]) == removed.end()) {
        l = combineScores(l, resp.score[k], scoring);
      }
    }
    for (const Rectangle& r : added) {
      const double s = model.surfaceScore(r.squaredDistance(points[p]));
      if (s >= min_score) {
        l = combineScores(l, s, scoring);
      }
    }
    change += l - pointScore(resp, p, s_star, scoring);
  }
  return change;
}

std::size_t distinctRows(const std::vector<std::int32_t>& rows,
                         const std::vector<std::int32_t>& members) {
  if (rows.empty()) {
    return 0;
  }
  std::vector<std::int32_t> r;
  r.reserve(members.size());
  for (const std::int32_t i : members) {
    r.push_back(rows[static_cast<std::size_t>(i)]);
  }
  std::sort(r.begin(), r.end());
  return static_cast<std::size_t>(std::unique(r.begin(), r.end()) - r.begin());
}

std::vector<std::int32_t> pointsNear(const PointGrid& grid,
                                     const std::vector<Eigen::Vector3d>& points,
                                     const Rectangle& rect, double cutoff_m) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const auto& c : rect.corners()) {
    lo = lo.cwiseMin(c);
    hi = hi.cwiseMax(c);
  }
  const Eigen::Vector3d pad = Eigen::Vector3d::Constant(cutoff_m);
  std::vector<std::int32_t> out = grid.inBox(lo - pad, hi + pad);
  const double c2 = cutoff_m * cutoff_m;
  out.erase(std::remove_if(out.begin(), out.end(),
                           [&](std::int32_t i) {
                             return rect.squaredDistance(points[static_cast<std::size_t>(i)]) > c2;
                           }),
            out.end());
  return out;
}

// Sorted lists (members, pointsNear) are merged, O(total); others sorted first.
std::vector<std::int32_t> unionOf(const std::vector<std::vector<std::int32_t>>& lists) {
  std::vector<std::int32_t> out;
  std::vector<std::int32_t> merged;
  std::vector<std::int32_t> sorted;
  for (const auto& l : lists) {
    const std::vector<std::int32_t>* next = &l;
    if (!std::is_sorted(l.begin(), l.end())) {
      sorted = l;
      std::sort(sorted.begin(), sorted.end());
      next = &sorted;
    }
    merged.clear();
    merged.reserve(out.size() + next->size());
    std::set_union(out.begin(), out.end(), next->begin(), next->end(), std::back_inserter(merged));
    out.swap(merged);
  }
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace pmap::em
