// Point-level scores of the map's surface assignment (points.ply `surface`)
// against the ground-truth labels: recall, precision, F1 and the rejection of
// clutter into the outlier class.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

#include "pmap/eval/ground_truth.h"
#include "pmap/eval/surface_matching.h"

namespace pmap::eval {

/// Points of one kind of true hit, and how many a map surface holds.
struct TruthCount {
  std::size_t points = 0;
  std::size_t on_map_surface = 0;
};

/// What a point's true ray hit, in the classes that say whether a plane
/// could explain it: a ground-truth rectangle ("rectangle"), a box or a
/// cylinder of clutter ("box", "cylinder"), a person walking through
/// ("person"), nothing (a spurious or mixed return, "no_object").
std::string truthClass(const GroundTruth& gt, int label);

struct LabelMetrics {
  std::size_t on_surface_points = 0;  ///< points labelled with an eligible surface
  std::size_t recalled_points = 0;    ///< ... on a map surface matching that label
  std::size_t assigned_points = 0;    ///< labelled points with a map surface (id >= 0)
  std::size_t correct_points = 0;     ///< ... whose map surface matches their label
  std::size_t clutter_points = 0;     ///< points labelled with a clutter object
  std::size_t clutter_rejected = 0;   ///< ... in the outlier class (surface -1)
  std::optional<double> recall;       ///< recalled / on_surface; none if no such points
  std::optional<double> precision;    ///< correct / assigned; none if nothing assigned
  std::optional<double> f1;           ///< harmonic mean of the two (0 if both are 0)
  std::optional<double> clutter_rejected_fraction;  ///< none if no clutter points
  /// Every labelled point by truthClass(): where the unexplained points are.
  std::map<std::string, TruthCount> by_truth;
};

/// `point_surfaces`: the points' map surface ids; `labels`: their
/// ground-truth labels (pointLabels; points without an entry are skipped);
/// `eligible`: ids of the eligible ground-truth surfaces.
LabelMetrics labelMetrics(const GroundTruth& gt, const std::vector<int>& point_surfaces,
                          const std::vector<int>& labels, const SurfaceMatches& matches,
                          const std::unordered_set<int>& eligible);

}  // namespace pmap::eval
