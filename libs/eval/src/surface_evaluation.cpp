#include "pmap/eval/surface_evaluation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_set>

#include "pmap/common/error.h"
#include "pmap/eval/point_labels.h"
#include "pmap/eval/rectangle_errors.h"
#include "pmap/eval/reference_surfaces.h"

namespace pmap::eval {
namespace {

// How far a clipped reference edge may lie from a shared edge and still be
// closed to it (the refinement's default seam_distance_m).
constexpr double kSeamReachM = 0.3;

// The spread of the planes of `matching` (map surface indices) along the
// reference's normal, at the clipped reference's centre.
double matchingSpread(const ReferenceSurface& ref, const std::vector<MapSurface>& surfaces,
                      const std::vector<std::size_t>& matching) {
  const Eigen::Vector3d c = rectangleCentre(ref.clipped);
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const std::size_t j : matching) {
    const MapSurface& m = surfaces[j];
    const double side = m.normal.dot(ref.rect.normal) < 0.0 ? -1.0 : 1.0;
    const double d = side * (m.normal.dot(c) - m.offset_m);  // along the reference's normal
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  return matching.size() > 1 ? hi - lo : 0.0;
}

SurfaceScore scoreSurface(const ReferenceSurface& ref, const MapSurface& map,
                          const MapSurfaceMatch& match, std::size_t matching,
                          const std::vector<GtSeam>& seams) {
  SurfaceScore s;
  s.gt_id = ref.rect.id;
  s.kind = ref.rect.kind;
  s.hits = ref.hits;
  s.map_id = map.id;
  s.map_surfaces_matching = matching;
  s.points = match.points;
  s.normal_error_deg = normalAngleDeg(map.normal, ref.rect.normal);
  s.offset_error_m = planeDistance(map.normal, map.offset_m, rectangleCentre(ref.clipped));
  s.corner_error_m = cornerError(map.corners, ref.clipped);
  s.corner_error_closed_m =
      cornerError(map.corners, closedReference(ref.rect, ref.clipped, seams, kSeamReachM));
  return s;
}

void addScore(const SurfaceScore& s, SurfaceEvaluation& e) {
  ++e.matched_surfaces;
  ++e.matched_by_kind[s.kind].matched;
  e.normal_error_deg.add(s.normal_error_deg);
  e.offset_error_m.add(s.offset_error_m);
  e.corner_error_m.add(s.corner_error_m);
  e.corner_error_closed_m.add(s.corner_error_closed_m);
  e.per_surface.push_back(s);
}

}  // namespace

std::string SurfaceEvalOptions::validate() const {
  if (min_hits == 0) {
    return "min_hits must be >= 1";
  }
  return match.validate();
}

void ErrorSummary::add(double value) {
  ++count;
  sum += value;
  max = std::max(max, value);
}

std::optional<double> ErrorSummary::mean() const {
  if (count == 0) {
    return std::nullopt;
  }
  return sum / static_cast<double>(count);
}

SurfaceEvaluation evaluateSurfaces(const GroundTruth& gt, const MapPoints& points,
                                   const std::vector<MapSurface>& surfaces,
                                   const Rigid2D& map_to_gt, const SurfaceEvalOptions& options) {
  if (const std::string rule = options.validate(); !rule.empty()) {
    throw ConfigError("surface evaluation options: " + rule);
  }
  std::vector<Eigen::Vector3d> xyz;
  xyz.reserve(points.xyz.size());
  for (const auto& p : points.xyz) {
    xyz.push_back(map_to_gt.apply(p));
  }
  std::vector<MapSurface> moved;
  for (const auto& s : surfaces) {
    moved.push_back(movedSurface(s, map_to_gt));
  }
  const std::vector<int> labels = pointLabels(gt, points);
  const auto refs = referenceSurfaces(gt, countHits(gt), xyz, labels, options.min_hits);
  const SurfaceMatches matches = matchSurfaces(gt, moved, points.surface, labels, options.match);

  SurfaceEvaluation e;
  e.surfaces = surfaces.size();
  e.gt_surfaces = refs.size();
  e.map_surfaces_unmatched = surfaces.size() - matches.gt_of_map.size();
  std::unordered_set<int> eligible;
  std::vector<std::pair<int, MapSurface>> primaries;
  std::vector<int> eligible_ids;
  for (const auto& ref : refs) {
    eligible_ids.push_back(ref.rect.id);
  }
  // The closed reference also closes a door's edges to its wall's opening.
  std::vector<GtSeam> closing = groundTruthSeams(gt, eligible_ids);
  const std::vector<GtSeam> openings = openingEdges(gt, eligible_ids);
  closing.insert(closing.end(), openings.begin(), openings.end());
  for (const auto& ref : refs) {
    eligible.insert(ref.rect.id);
    ++e.matched_by_kind[ref.rect.kind].gt;
    const auto it = matches.by_gt.find(ref.rect.id);
    if (it == matches.by_gt.end()) {
      e.unmatched.push_back({ref.rect.id, ref.rect.kind, ref.hits});
      continue;
    }
    const std::size_t primary = it->second.front();
    primaries.emplace_back(ref.rect.id, moved[primary]);
    SurfaceScore score = scoreSurface(ref, moved[primary], matches.map_surfaces[primary],
                                      it->second.size(), closing);
    score.matching_spread_m = matchingSpread(ref, moved, it->second);
    addScore(score, e);
  }
  e.seams = seamSides(gt, primaries);
  for (const SeamSide& side : e.seams) {
    e.seam_gap_m.add(std::abs(side.gap_m));
  }
  e.labels = labelMetrics(gt, points.surface, labels, matches, eligible);
  return e;
}

}  // namespace pmap::eval
