#include "pmap/eval/point_labels.h"

namespace pmap::eval {

std::vector<int> pointLabels(const GroundTruth& gt, const MapPoints& points) {
  std::vector<int> labels(points.xyz.size(), kNoLabelEntry);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const auto it = gt.hits.find(points.scan[i]);
    if (it == gt.hits.end() || points.beam[i] < 0 ||
        static_cast<std::size_t>(points.beam[i]) >= it->second.size()) {
      continue;
    }
    labels[i] = it->second[static_cast<std::size_t>(points.beam[i])];
  }
  return labels;
}

std::unordered_map<int, std::size_t> countHits(const GroundTruth& gt) {
  std::unordered_map<int, std::size_t> hits;
  for (const auto& [scan, beams] : gt.hits) {
    for (const int id : beams) {
      if (id >= 0) {
        ++hits[id];
      }
    }
  }
  return hits;
}

}  // namespace pmap::eval
