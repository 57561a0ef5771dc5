#include "pmap/eval/surface_matching.h"

#include <algorithm>

#include "pmap/eval/point_labels.h"
#include "pmap/eval/rectangle_errors.h"

namespace pmap::eval {
namespace {

using LabelCounts = std::unordered_map<int, std::size_t>;  // label -> points

/// Per map surface id: how many of its points carry each label.
std::unordered_map<int, LabelCounts> countLabels(const std::vector<int>& point_surfaces,
                                                 const std::vector<int>& labels) {
  std::unordered_map<int, LabelCounts> counts;
  for (std::size_t i = 0; i < point_surfaces.size(); ++i) {
    if (point_surfaces[i] >= 0 && labels[i] != kNoLabelEntry) {
      ++counts[point_surfaces[i]][labels[i]];
    }
  }
  return counts;
}

MapSurfaceMatch matchOne(const MapSurface& s, const LabelCounts& counts,
                         const std::unordered_map<int, const GtRectangle*>& rects,
                         const SurfaceMatchOptions& options) {
  MapSurfaceMatch m;
  m.map_id = s.id;
  for (const auto& [label, n] : counts) {
    m.points += n;
    const bool better =
        n > m.majority_points || (n == m.majority_points && label < m.majority_label);
    if (rects.count(label) != 0 && better) {
      m.majority_label = label;
      m.majority_points = n;
    }
  }
  if (m.majority_label < 0) {
    return m;
  }
  m.normal_angle_deg = normalAngleDeg(s.normal, rects.at(m.majority_label)->normal);
  const double share = static_cast<double>(m.majority_points) / static_cast<double>(m.points);
  if (share >= options.min_label_share && m.normal_angle_deg <= options.max_normal_angle_deg) {
    m.gt_id = m.majority_label;
  }
  return m;
}

}  // namespace

std::string SurfaceMatchOptions::validate() const {
  if (!(min_label_share >= 0.5 && min_label_share <= 1.0)) {
    return "min_label_share must be in [0.5, 1] (a map surface matches at most one surface)";
  }
  if (!(max_normal_angle_deg >= 0.0 && max_normal_angle_deg <= 90.0)) {
    return "max_normal_angle_deg must be in [0, 90]";
  }
  return {};
}

int SurfaceMatches::matchedGt(int map_id) const {
  const auto it = gt_of_map.find(map_id);
  return it == gt_of_map.end() ? -1 : it->second;
}

SurfaceMatches matchSurfaces(const GroundTruth& gt, const std::vector<MapSurface>& surfaces,
                             const std::vector<int>& point_surfaces, const std::vector<int>& labels,
                             const SurfaceMatchOptions& options) {
  std::unordered_map<int, const GtRectangle*> rects;
  for (const auto& r : gt.surfaces) {
    rects[r.id] = &r;
  }
  const auto counts = countLabels(point_surfaces, labels);
  const LabelCounts none;
  SurfaceMatches result;
  for (const auto& s : surfaces) {
    const auto it = counts.find(s.id);
    result.map_surfaces.push_back(
        matchOne(s, it == counts.end() ? none : it->second, rects, options));
    const MapSurfaceMatch& m = result.map_surfaces.back();
    if (m.gt_id >= 0) {
      result.gt_of_map[m.map_id] = m.gt_id;
      result.by_gt[m.gt_id].push_back(result.map_surfaces.size() - 1);
    }
  }
  for (auto& [gt_id, list] : result.by_gt) {
    std::sort(list.begin(), list.end(), [&](std::size_t a, std::size_t b) {
      const auto& ma = result.map_surfaces[a];
      const auto& mb = result.map_surfaces[b];
      return ma.points != mb.points ? ma.points > mb.points : ma.map_id < mb.map_id;
    });
  }
  return result;
}

}  // namespace pmap::eval
