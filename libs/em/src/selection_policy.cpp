#include "pmap/em/selection_policy.h"

#include <algorithm>
#include <cmath>

#include "pmap/em/model_selection.h"
#include "pmap/em/planarity.h"
#include "pmap/em/surface_fit.h"

namespace pmap::em {

bool seenByEnoughRows(const Measurements& z, const std::vector<std::int32_t>& members,
                      const PlanarEmOptions& o) {
  if (z.rows.empty()) {
    return true;
  }
  // Stops at the min_rows-th distinct row (a handful), not sorting them all.
  const auto needed = static_cast<std::size_t>(o.min_rows);
  std::vector<std::int32_t> seen;
  for (const std::int32_t i : members) {
    const std::int32_t r = z.rows[static_cast<std::size_t>(i)];
    if (std::find(seen.begin(), seen.end(), r) == seen.end()) {
      seen.push_back(r);
      if (seen.size() >= needed) {
        return true;
      }
    }
  }
  return seen.size() >= needed;
}

bool curvedSurface(const Measurements& z, const std::vector<std::int32_t>& members,
                   const Rectangle& rect, const PlanarEmOptions& o) {
  return isCurved(measurePlanarity(z.points, members, rect), o.min_curvature_radius_m,
                  o.min_curvature_depth_m, o.rules.curved_min_variance_explained);
}

SurfaceVerdict checkSurface(const Measurements& z, const std::vector<std::int32_t>& members,
                            const Rectangle& rect, const PlanarEmOptions& o,
                            std::size_t min_points) {
  SurfaceVerdict c;
  c.enough_points = members.size() >= min_points;
  c.curved = curvedSurface(z, members, rect, o);
  c.enough_rows = c.enough_points && !c.curved && seenByEnoughRows(z, members, o);
  return c;
}

bool fitValidSurface(const Measurements& z, const std::vector<std::int32_t>& members,
                     Rectangle& rect, const PlanarEmOptions& o, std::size_t min_points) {
  // Cheapest test first; planarity (a least-squares fit) last.
  return members.size() >= min_points && fitSurface(z.points, members, rect) == FitStatus::kOk &&
         seenByEnoughRows(z, members, o) && !curvedSurface(z, members, rect, o);
}

double rectangleGap(const Rectangle& a, const Rectangle& b) {
  double gap2 = std::min(a.squaredDistance(b.centre), b.squaredDistance(a.centre));
  for (const auto& c : a.corners()) {
    gap2 = std::min(gap2, b.squaredDistance(c));
  }
  for (const auto& c : b.corners()) {
    gap2 = std::min(gap2, a.squaredDistance(c));
  }
  return std::sqrt(gap2);
}

bool fusionPartners(const Rectangle& a, const Rectangle& b, const PlanarEmOptions& o) {
  const double cos_max = std::cos(o.fuse_angle_deg * M_PI / 180.0);
  return std::abs(a.normal.dot(b.normal)) >= cos_max &&
         std::abs(a.planeDistance(b.centre)) <= o.fuse_offset_m &&
         std::abs(b.planeDistance(a.centre)) <= o.fuse_offset_m &&
         rectangleGap(a, b) <= o.fuse_gap_m + o.fuse_offset_m;
}

bool sameSurfacePlace(const Rectangle& a, const Rectangle& b, double max_separation_m,
                      const PlanarEmOptions& o) {
  if (std::abs(a.normal.dot(b.normal)) < std::cos(o.fuse_angle_deg * M_PI / 180.0)) {
    return false;
  }
  // Project the smaller onto the larger (less shrinking by the angle).
  const bool a_larger = a.area() >= b.area();
  const Overlap ov = a_larger ? overlapOf(a, b) : overlapOf(b, a);
  const double smaller = std::min(a.area(), b.area());
  return ov.area_m2 * 100.0 >= smaller * o.rules.same_place_overlap_percent &&
         ov.max_separation_m <= max_separation_m;
}

double posteriorGain(double loglik_change, int surfaces_added, double empty_area_change_m2,
                     const PlanarEmOptions& o) {
  return loglik_change - o.kappa * static_cast<double>(surfaces_added) -
         o.empty_area_cost * empty_area_change_m2;
}

bool raisesPosterior(double gain, const PlanarEmOptions& o) {
  return gain > o.min_gain;
}

bool recutAffordable(double gain, const PlanarEmOptions& o) {
  return gain > -o.min_gain;
}

bool recutGrowsLarger(std::size_t larger_after, std::size_t larger_before,
                      const PlanarEmOptions& o) {
  const auto percent = static_cast<std::size_t>(100 + o.rules.recut_min_growth_percent);
  return larger_after * 100 > larger_before * percent;
}

bool recutLeavesSmaller(std::size_t moving, std::size_t smaller, const PlanarEmOptions& o) {
  return moving * 100 <= smaller * static_cast<std::size_t>(o.rules.recut_max_transfer_percent);
}

bool sameAsRemoved(const Rectangle& candidate, const Rectangle& removed, const PlanarEmOptions& o) {
  const SelectionRules& r = o.rules;
  return std::abs(candidate.normal.dot(removed.normal)) >
             std::cos(r.tabu_angle_deg * M_PI / 180.0) &&
         std::abs(removed.planeDistance(candidate.centre)) < r.tabu_offset_sigmas * o.sigma_m &&
         (candidate.centre - removed.centre).norm() <
             r.tabu_centre_m + r.tabu_centre_per_side * std::sqrt(removed.area());
}

bool coverageJudged(double area_m2, std::size_t sampled, const PlanarEmOptions& o) {
  return area_m2 >= o.rules.poor_coverage_min_area_m2 &&
         sampled >= static_cast<std::size_t>(o.rules.poor_coverage_min_points);
}

double coverageCell(double area_m2, std::size_t sampled) {
  return 2.0 * std::sqrt(area_m2 / static_cast<double>(sampled));
}

bool poorlyCovered(double empty_m2, double area_m2, const PlanarEmOptions& o) {
  return empty_m2 > o.rules.poor_coverage_empty_fraction * area_m2;
}

std::size_t minSplitPart(double scale, const PlanarEmOptions& o) {
  return static_cast<std::size_t>(std::max(static_cast<double>(o.rules.min_part_points),
                                           static_cast<double>(o.min_support) / scale));
}

double sampledSplitCell(double area_m2, std::size_t sampled, const PlanarEmOptions& o) {
  return std::max(o.split_cell_m, o.rules.sampled_cell_spacings *
                                      std::sqrt(area_m2 / static_cast<double>(sampled)));
}

double growDistance(const PlanarEmOptions& o) {
  return o.rules.grow_sigmas * o.sigma_m;
}

}  // namespace pmap::em
