// Ground-truth labels of the mapped points: the id of the object the true ray
// of each point's beam hit (gt.json structure_scans), and hit counts per id.
// A map made without the ground truth's scans (planar-mapper --cloud) has no
// beams to look up: its points are labelled by the nearest object instead.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "pmap/eval/ground_truth.h"
#include "pmap/eval/map_files.h"

namespace pmap::eval {

/// Label of a point whose (scan, beam) has no entry in the ground truth.
constexpr int kNoLabelEntry = -2;

/// Per mapped point: the id its beam's true ray hit, -1 for nothing,
/// kNoLabelEntry when gt.json has no such scan or beam.
std::vector<int> pointLabels(const GroundTruth& gt, const MapPoints& points);

/// Number of beams of all structure scans in gt.json that hit each id
/// (posters count as their wall; -1 is not counted).
std::unordered_map<int, std::size_t> countHits(const GroundTruth& gt);

/// Labels by proximity, for a map whose points are not the ground truth's
/// beams (a `--cloud` map; its points.ply numbers them scan 0, beam i).
struct NearestLabelOptions {
  /// A point farther than this from every object is labelled -1 (m); map-eval
  /// uses 3 sigma of the ground truth's range noise, at least 1 cm.
  double max_distance_m = 0.06;
  /// Grid cell (x, y) of the object index (m); widened so that the grid
  /// has at most 2^22 cells.
  double cell_m = 1.0;
  bool validate(std::string* why) const;
};

/// Ground-truth `hits` for the map's own points: hits[scan][beam] is the id
/// of the object (rectangle, cylinder or box) nearest to that point of
/// `points`, -1 when none is within max_distance_m; ties go to the lower id;
/// beams no point has are -1. Replacing gt.hits with it lets the label
/// based scores run on such a map. Throws InputError when a scan or beam
/// index is negative, or a beam index is past 4 times the number of points
/// (plus 65,536; no real map numbers its beams that sparsely).
std::map<std::int64_t, std::vector<int>> nearestObjectHits(const GroundTruth& gt,
                                                           const MapPoints& points,
                                                           const NearestLabelOptions& options);

}  // namespace pmap::eval
