#include "pmap/eval/point_labels.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <unordered_map>

#include "pmap/common/error.h"

namespace pmap::eval {
namespace {

// One ground-truth object as the nearest-object search sees it: its id, the
// box of its x, y extent and its distance function.
struct Object {
  int id = -1;
  Eigen::Vector2d lo, hi;
  std::function<double(const Eigen::Vector3d&)> distance;
};

std::vector<Object> objectsOf(const GroundTruth& gt) {
  std::vector<Object> out;
  for (const GtRectangle& r : gt.surfaces) {
    Eigen::Vector2d lo = r.corners[0].head<2>(), hi = lo;
    for (const auto& c : r.corners) {
      lo = lo.cwiseMin(c.head<2>());
      hi = hi.cwiseMax(c.head<2>());
    }
    out.push_back({r.id, lo, hi,
                   [&r](const Eigen::Vector3d& p) { return distanceToRectangle(r.corners, p); }});
  }
  for (const GtCylinder& c : gt.cylinders) {
    const Eigen::Vector2d reach = Eigen::Vector2d::Constant(c.radius);
    out.push_back({c.id, c.centre - reach, c.centre + reach,
                   [&c](const Eigen::Vector3d& p) { return distanceToCylinder(c, p); }});
  }
  for (const GtBox& b : gt.boxes) {
    double r = 0;  // the farthest corner from the centre, in x, y
    for (const double x : {b.min.x(), b.max.x()}) {
      for (const double y : {b.min.y(), b.max.y()}) {
        r = std::max(r, std::hypot(x, y));
      }
    }
    const Eigen::Vector2d reach = Eigen::Vector2d::Constant(r);
    out.push_back({b.id, b.centre - reach, b.centre + reach,
                   [&b](const Eigen::Vector3d& p) { return distanceToBox(b, p); }});
  }
  std::sort(out.begin(), out.end(), [](const Object& a, const Object& b) { return a.id < b.id; });
  return out;
}

// The objects on a grid of x, y cells, each in every cell its box (grown by
// the label distance) touches, in increasing id.
class ObjectGrid {
 public:
  ObjectGrid(const std::vector<Object>& objects, double reach, double cell_m) {
    if (objects.empty()) {
      return;
    }
    Eigen::Vector2d lo = objects.front().lo, hi = objects.front().hi;
    for (const Object& o : objects) {
      lo = lo.cwiseMin(o.lo);
      hi = hi.cwiseMax(o.hi);
    }
    const double span = (hi - lo).maxCoeff() + 2.0 * reach;
    cell_ = std::max(cell_m, span / 2048.0);  // at most 2048 x 2048 cells
    for (std::size_t k = 0; k < objects.size(); ++k) {
      const Eigen::Vector2d a = objects[k].lo.array() - reach, b = objects[k].hi.array() + reach;
      for (std::int64_t y = cellOf(a.y()); y <= cellOf(b.y()); ++y) {
        for (std::int64_t x = cellOf(a.x()); x <= cellOf(b.x()); ++x) {
          cells_[key(x, y)].push_back(k);
        }
      }
    }
  }
  /// The objects whose grown box may hold p (none when p is in no cell).
  const std::vector<std::size_t>& near(const Eigen::Vector3d& p) const {
    static const std::vector<std::size_t> kNone;
    const auto it = cells_.find(key(cellOf(p.x()), cellOf(p.y())));
    return it == cells_.end() ? kNone : it->second;
  }

 private:
  std::int64_t cellOf(double v) const { return static_cast<std::int64_t>(std::floor(v / cell_)); }
  static std::int64_t key(std::int64_t x, std::int64_t y) {
    return static_cast<std::int64_t>((static_cast<std::uint64_t>(x) << 32) ^
                                     (static_cast<std::uint64_t>(y) & 0xffffffffULL));
  }
  double cell_ = 1.0;
  std::unordered_map<std::int64_t, std::vector<std::size_t>> cells_;
};

}  // namespace

bool NearestLabelOptions::validate(std::string* why) const {
  if (!(max_distance_m > 0.0 && std::isfinite(max_distance_m)) ||
      !(cell_m > 0.0 && std::isfinite(cell_m))) {
    *why = "max_distance_m and cell_m must be finite and > 0";
    return false;
  }
  return true;
}

std::map<std::int64_t, std::vector<int>> nearestObjectHits(const GroundTruth& gt,
                                                           const MapPoints& points,
                                                           const NearestLabelOptions& options) {
  if (std::string why; !options.validate(&why)) {
    throw ConfigError("nearest-object labels: " + why);
  }
  const std::size_t n = points.xyz.size();
  const auto max_beam = static_cast<std::int64_t>(4 * n + 65536);
  std::map<std::int64_t, std::vector<int>> hits;
  for (std::size_t i = 0; i < n; ++i) {  // every index checked before any work
    if (points.scan[i] < 0 || points.beam[i] < 0 || points.beam[i] >= max_beam) {
      throw InputError("points.ply vertex " + std::to_string(i) + ": scan " +
                       std::to_string(points.scan[i]) + ", beam " + std::to_string(points.beam[i]) +
                       " out of range for a map of " + std::to_string(n) + " points");
    }
    std::vector<int>& beams = hits[points.scan[i]];
    if (static_cast<std::size_t>(points.beam[i]) >= beams.size()) {
      beams.resize(static_cast<std::size_t>(points.beam[i]) + 1, -1);
    }
  }
  const std::vector<Object> objects = objectsOf(gt);
  const ObjectGrid grid(objects, options.max_distance_m, options.cell_m);
  for (std::size_t i = 0; i < n; ++i) {
    double best = options.max_distance_m;
    int label = -1;
    for (const std::size_t k : grid.near(points.xyz[i])) {  // increasing id: ties keep the lower
      const double d = objects[k].distance(points.xyz[i]);
      if (d <= best && (label < 0 || d < best)) {
        best = d;
        label = objects[k].id;
      }
    }
    hits[points.scan[i]][static_cast<std::size_t>(points.beam[i])] = label;
  }
  return hits;
}

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
