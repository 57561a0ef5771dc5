#include "pmap/eval/label_metrics.h"

#include <unordered_map>

#include "pmap/eval/point_labels.h"

namespace pmap::eval {
namespace {

std::optional<double> ratio(std::size_t num, std::size_t den) {
  if (den == 0) {
    return std::nullopt;
  }
  return static_cast<double>(num) / static_cast<double>(den);
}

std::unordered_set<int> clutterIds(const GroundTruth& gt) {
  std::unordered_set<int> ids;
  for (const auto& c : gt.cylinders) {
    ids.insert(c.id);
  }
  for (const auto& b : gt.boxes) {
    ids.insert(b.id);
  }
  ids.insert(gt.people.begin(), gt.people.end());  // people walking through: clutter that moves
  return ids;
}

}  // namespace

std::string truthClass(const GroundTruth& gt, int label) {
  if (label < 0) {
    return "no_object";
  }
  if (gt.surface(label) != nullptr) {
    return "rectangle";
  }
  for (const GtCylinder& c : gt.cylinders) {
    if (c.id == label) {
      return "cylinder";
    }
  }
  for (const GtBox& b : gt.boxes) {
    if (b.id == label) {
      return "box";
    }
  }
  return gt.isPerson(label) ? "person" : "unknown";
}

LabelMetrics labelMetrics(const GroundTruth& gt, const std::vector<int>& point_surfaces,
                          const std::vector<int>& labels, const SurfaceMatches& matches,
                          const std::unordered_set<int>& eligible) {
  const std::unordered_set<int> clutter = clutterIds(gt);
  LabelMetrics m;
  std::unordered_map<int, TruthCount*> truth_of;  // std::map's elements stay put
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const int label = labels[i];
    const int surface = point_surfaces[i];
    if (label == kNoLabelEntry) {
      continue;
    }
    auto slot = truth_of.find(label);  // one look-up of each label's class
    if (slot == truth_of.end()) {
      slot = truth_of.emplace(label, &m.by_truth[truthClass(gt, label)]).first;
    }
    TruthCount& t = *slot->second;
    ++t.points;
    t.on_map_surface += surface >= 0 ? 1 : 0;
    const bool correct = surface >= 0 && label >= 0 && matches.matchedGt(surface) == label;
    if (eligible.count(label) != 0) {
      ++m.on_surface_points;
      m.recalled_points += correct ? 1 : 0;
    }
    if (surface >= 0) {
      ++m.assigned_points;
      m.correct_points += correct ? 1 : 0;
    }
    if (clutter.count(label) != 0) {
      ++m.clutter_points;
      m.clutter_rejected += surface == -1 ? 1 : 0;
    }
  }
  m.recall = ratio(m.recalled_points, m.on_surface_points);
  m.precision = ratio(m.correct_points, m.assigned_points);
  if (m.recall && m.precision) {
    const double sum = *m.recall + *m.precision;
    m.f1 = sum > 0 ? 2.0 * *m.recall * *m.precision / sum : 0.0;
  }
  m.clutter_rejected_fraction = ratio(m.clutter_rejected, m.clutter_points);
  return m;
}

}  // namespace pmap::eval
