// Ground-truth labels of the mapped points: the id of the object the true ray
// of each point's beam hit (gt.json structure_scans), and hit counts per id.
#pragma once

#include <cstddef>
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

}  // namespace pmap::eval
