// Matching map surfaces (surfaces.csv + points.ply ids) to ground-truth
// surfaces through the ground-truth labels of their points.
#pragma once

#include <cstddef>
#include <string>
#include <unordered_map>
#include <vector>

#include "pmap/eval/ground_truth.h"
#include "pmap/eval/surface_files.h"

namespace pmap::eval {

struct SurfaceMatchOptions {
  /// A map surface matches its most frequent ground-truth surface label when
  /// at least this share of its labelled points carry it (0.5 < x <= 1 keeps
  /// the match unique; 0.5 is allowed, ties go to the lower id).
  double min_label_share = 0.5;
  /// ... and their normals agree within this angle, sign-agnostic (degrees).
  double max_normal_angle_deg = 10.0;
  /// Empty if valid, otherwise the violated rule.
  std::string validate() const;
};

struct MapSurfaceMatch {
  int map_id = -1;
  std::size_t points = 0;           ///< its points whose beam has a ground-truth label entry
  int majority_label = -1;          ///< its most frequent ground-truth rectangle label, -1: none
  std::size_t majority_points = 0;  ///< its points carrying that label
  double normal_angle_deg = 90.0;   ///< between its normal and the majority label's
  int gt_id = -1;                   ///< the ground-truth surface it matches, -1: none
};

struct SurfaceMatches {
  std::vector<MapSurfaceMatch> map_surfaces;  ///< one per map surface, in surfaces.csv order
  /// Ground-truth id -> indices into map_surfaces of the map surfaces
  /// matching it; the primary match (most points, then lowest map id) first.
  std::unordered_map<int, std::vector<std::size_t>> by_gt;
  /// Map surface id -> the ground-truth surface it matches (matched ones only).
  std::unordered_map<int, int> gt_of_map;
  /// The ground-truth surface map surface `map_id` matches, -1 for none.
  int matchedGt(int map_id) const;
};

/// `surfaces` in the ground-truth frame; `point_surfaces` the points' map
/// surface ids (points.ply), `labels` their ground-truth labels (pointLabels).
SurfaceMatches matchSurfaces(const GroundTruth& gt, const std::vector<MapSurface>& surfaces,
                             const std::vector<int>& point_surfaces, const std::vector<int>& labels,
                             const SurfaceMatchOptions& options);

}  // namespace pmap::eval
