// The decisions of model selection (eq. 30 and the rules beyond the paper)
// as plain functions of the measurements and the surfaces they are asked
// about, used by both the offline selector (model_selector.cpp: all points,
// every round) and the online EM (online_selection.cpp, online_fusion.cpp,
// online_split.cpp: a capped subsample and the hull, one surface per turn).
// Offline and online differ only in the points they pass and in how much
// work per step they allow; every threshold is a PlanarEmOptions field
// (selection_rules.h for the fixed ones).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "pmap/em/planar_em_options.h"
#include "pmap/em/rectangle.h"

namespace pmap::em {

/// What model selection looks at: the measurements and, per measurement,
/// its row (scan; may be empty: the min_rows test is then skipped).
struct Measurements {
  const std::vector<Eigen::Vector3d>& points;
  const std::vector<std::int32_t>& rows;
};

/// The validity tests of a fitted surface (beyond the paper; doc/em.md).
struct SurfaceVerdict {
  bool enough_points = false;  ///< at least the required number of members
  /// Seen by at least min_rows scans (or no rows known); only tested when
  /// the other two tests pass (false otherwise: it decides nothing then).
  bool enough_rows = false;
  bool curved = false;  ///< bends with a radius below min_curvature_radius_m
  bool valid() const { return enough_points && enough_rows && !curved; }
};

/// Whether `members` come from at least min_rows distinct rows (true when no
/// rows are known): one vertical scan is itself an exact plane.
bool seenByEnoughRows(const Measurements& z, const std::vector<std::int32_t>& members,
                      const PlanarEmOptions& o);

/// Whether `members` bend on `rect` with a radius below min_curvature_radius_m
/// (planarity.h): a bin or a column, not a plane.
bool curvedSurface(const Measurements& z, const std::vector<std::int32_t>& members,
                   const Rectangle& rect, const PlanarEmOptions& o);

/// Support, planarity and rows of `members` on `rect`; `min_points` is the
/// support required (min_support, or its share of a subsample).
SurfaceVerdict checkSurface(const Measurements& z, const std::vector<std::int32_t>& members,
                            const Rectangle& rect, const PlanarEmOptions& o,
                            std::size_t min_points);

/// Fits `rect` (plane and rectangle, eqs. 24-29) to `members` and checks it:
/// a valid surface of at least `min_points` members.
bool fitValidSurface(const Measurements& z, const std::vector<std::int32_t>& members,
                     Rectangle& rect, const PlanarEmOptions& o, std::size_t min_points);

/// Shortest distance between two rectangles, from their corners and centres (m).
double rectangleGap(const Rectangle& a, const Rectangle& b);

/// Whether two surfaces may be the same plane and are tested for fusion (or
/// an L re-cut): normals within fuse_angle_deg, each centre within
/// fuse_offset_m of the other's plane, rectangles within fuse_gap_m (plus
/// fuse_offset_m) of each other.
bool fusionPartners(const Rectangle& a, const Rectangle& b, const PlanarEmOptions& o);

/// Whether two surfaces occupy the same place (SelectionRules::
/// same_place_*): planes within `max_separation_m` of each other over an
/// overlap of at least same_place_overlap_percent of the smaller one.
/// Existing surfaces that do at split_min_offset_m are fused; a new surface
/// may not be created where it would at same_place_clearance times that.
bool sameSurfacePlace(const Rectangle& a, const Rectangle& b, double max_separation_m,
                      const PlanarEmOptions& o);

/// Eq. (30): the change of log p(Theta | Z) of a model-selection step, from
/// the change of the summed point scores (nats), the surfaces it adds (< 0:
/// removes) and the change of the rectangles' empty area (m^2, > 0: more
/// empty area).
double posteriorGain(double loglik_change, int surfaces_added, double empty_area_change_m2,
                     const PlanarEmOptions& o);

/// A removal, fusion, split or seed is made when it raises the log
/// posterior by more than min_gain (hysteresis).
bool raisesPosterior(double gain, const PlanarEmOptions& o);

/// A re-cut into the canonical form (no surface added or removed) is made
/// when it costs less than min_gain.
bool recutAffordable(double gain, const PlanarEmOptions& o);

/// A re-cut must grow the larger surface from `larger_before` to
/// `larger_after` points by more than recut_min_growth_percent.
bool recutGrowsLarger(std::size_t larger_after, std::size_t larger_before,
                      const PlanarEmOptions& o);

/// An online re-cut moves at most recut_max_transfer_percent of the smaller
/// surface's `smaller` points.
bool recutLeavesSmaller(std::size_t moving, std::size_t smaller, const PlanarEmOptions& o);

/// Whether `candidate` re-creates a surface `removed` recently (tabu).
bool sameAsRemoved(const Rectangle& candidate, const Rectangle& removed, const PlanarEmOptions& o);

/// Whether a rectangle of `area_m2` with `sampled` points is large and seen
/// enough for the coverage test below (online).
bool coverageJudged(double area_m2, std::size_t sampled, const PlanarEmOptions& o);
/// The cell of that test, holding ~4 sampled points (m).
double coverageCell(double area_m2, std::size_t sampled);
/// Whether its points leave `empty_m2` of the rectangle's `area_m2` mostly
/// empty: it is tested for a coverage cut at once.
bool poorlyCovered(double empty_m2, double area_m2, const PlanarEmOptions& o);

/// Smallest split part in sampled points, `scale` members per sampled point.
std::size_t minSplitPart(double scale, const PlanarEmOptions& o);

/// Grid cell of the split tests on `sampled` points of a rectangle of
/// `area_m2` (m): split_cell_m, coarser when the sample is sparse.
double sampledSplitCell(double area_m2, std::size_t sampled, const PlanarEmOptions& o);

/// Distance within which a point belongs to a plane when growing (m).
double growDistance(const PlanarEmOptions& o);

}  // namespace pmap::em
