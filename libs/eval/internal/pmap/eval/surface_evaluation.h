// Surface evaluation of a map (surfaces.csv + points.ply) against the ground
// truth: matched surfaces, their normal / offset / corner errors and the
// point-level label scores (doc/evaluation.md).
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "pmap/eval/ground_truth.h"
#include "pmap/eval/label_metrics.h"
#include "pmap/eval/map_files.h"
#include "pmap/eval/pose_metrics.h"
#include "pmap/eval/seam_gaps.h"
#include "pmap/eval/surface_files.h"
#include "pmap/eval/surface_matching.h"

namespace pmap::eval {

struct SurfaceEvalOptions {
  /// Ground-truth surfaces hit by fewer beams (all structure scans of
  /// gt.json) are not scored.
  std::size_t min_hits = 200;
  SurfaceMatchOptions match;
  /// Empty if valid, otherwise the violated rule.
  std::string validate() const;
};

/// Mean and maximum of a per-surface error.
struct ErrorSummary {
  std::size_t count = 0;
  double sum = 0;
  double max = 0;
  void add(double value);
  std::optional<double> mean() const;  ///< none when count == 0
};

/// A matched eligible ground-truth surface and its primary match.
struct SurfaceScore {
  int gt_id = -1;
  std::string kind;
  std::size_t hits = 0;
  int map_id = -1;                        ///< the primary match
  std::size_t map_surfaces_matching = 0;  ///< map surfaces matching it
  std::size_t points = 0;                 ///< labelled points of the primary match
  double normal_error_deg = 0;            ///< sign-agnostic angle between the normals
  double offset_error_m = 0;              ///< clipped reference centre to the map plane
  double corner_error_m = 0;              ///< cornerError(map rectangle, clipped reference)
  double corner_error_closed_m = 0;       ///< ... reference closed to its seams (seam_gaps.h)
  /// How far apart the planes of the map surfaces matching it lie, at the
  /// clipped reference's centre (m; 0 with one): a wall mapped twice as two
  /// parallel surfaces shows their distance here.
  double matching_spread_m = 0;
};

struct UnmatchedSurface {
  int id = -1;
  std::string kind;
  std::size_t hits = 0;
};

struct KindCounts {
  std::size_t gt = 0;       ///< eligible surfaces of the kind
  std::size_t matched = 0;  ///< ... matched
};

struct SurfaceEvaluation {
  std::size_t surfaces = 0;                ///< map surfaces (rows of surfaces.csv)
  std::size_t map_surfaces_unmatched = 0;  ///< map surfaces matching no ground-truth surface
  std::size_t gt_surfaces = 0;             ///< eligible ground-truth surfaces
  std::size_t matched_surfaces = 0;        ///< ... matched by at least one map surface
  std::map<std::string, KindCounts> matched_by_kind;
  std::vector<UnmatchedSurface> unmatched;  ///< eligible, not matched; by id
  std::vector<SurfaceScore> per_surface;    ///< matched eligible surfaces; by id
  ErrorSummary normal_error_deg;
  ErrorSummary offset_error_m;
  ErrorSummary corner_error_m;
  ErrorSummary corner_error_closed_m;
  /// Seams between matched eligible surfaces (seam_gaps.h) and |gap_m| over them.
  std::vector<SeamSide> seams;
  ErrorSummary seam_gap_m;
  LabelMetrics labels;
};

/// `points` and `surfaces` as read (map frame); `map_to_gt` moves them into
/// the ground-truth frame. Throws ConfigError for invalid options.
SurfaceEvaluation evaluateSurfaces(const GroundTruth& gt, const MapPoints& points,
                                   const std::vector<MapSurface>& surfaces,
                                   const Rigid2D& map_to_gt,
                                   const SurfaceEvalOptions& options = {});

}  // namespace pmap::eval
