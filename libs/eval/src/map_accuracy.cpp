#include "pmap/eval/map_accuracy.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <unordered_set>

#include "pmap/eval/point_labels.h"

namespace pmap::eval {
namespace {

std::int64_t cubeKey(const Eigen::Vector3d& p, double edge) {
  const Eigen::Array3d c = (p.array() / edge).floor();
  const auto part = [](double v) { return (static_cast<std::int64_t>(v) + (1 << 20)) & 0x1FFFFF; };
  return part(c.x()) | part(c.y()) << 21 | part(c.z()) << 42;
}

/// Distance to the nearest ground-truth object: rectangles through a tree,
/// clutter (cylinders, boxes: a handful) directly.
class GroundTruthDistance {
 public:
  GroundTruthDistance(const GroundTruth& gt, const TriangleIndexOptions& options)
      : gt_(gt), index_(groundTruthTriangles(gt), options) {}
  double operator()(const Eigen::Vector3d& p) const {
    double d = index_.distance(p);
    for (const GtCylinder& c : gt_.cylinders)
      d = std::min(d, gt_.distance(c.id, p));
    for (const GtBox& b : gt_.boxes)
      d = std::min(d, gt_.distance(b.id, p));
    return d;
  }

 private:
  const GroundTruth& gt_;
  TriangleIndex index_;
};

ErrorStats gtToMap(const std::vector<Eigen::Vector3d>& gt_samples, const TriangleIndex& map) {
  std::vector<double> d;
  d.reserve(gt_samples.size());
  for (const Eigen::Vector3d& s : gt_samples)
    d.push_back(map.distance(s));
  return errorStats(d, std::vector<double>(d.size(), 1.0));
}

ErrorStats mapToGt(const WeightedPoints& samples, const GroundTruth& gt,
                   const AccuracyOptions& options) {
  const GroundTruthDistance distance(gt, options.index);
  std::vector<double> d;
  d.reserve(samples.xyz.size());
  for (const Eigen::Vector3d& p : samples.xyz)
    d.push_back(distance(p));
  return errorStats(d, samples.weight);
}

std::array<Triangle3, 2> halves(const std::array<Eigen::Vector3d, 4>& c) {
  return {Triangle3{c[0], c[1], c[2]}, Triangle3{c[0], c[2], c[3]}};
}

}  // namespace

bool AccuracyOptions::validate(std::string* why) const {
  if (!(sample_spacing_m > 0.0 && std::isfinite(sample_spacing_m))) {
    if (why != nullptr)
      *why = "sample_spacing_m must be > 0";
    return false;
  }
  if (!(mesh_sample_m > 0.0 && std::isfinite(mesh_sample_m))) {
    if (why != nullptr)
      *why = "mesh_sample_m must be > 0";
    return false;
  }
  return index.validate(why);
}

ErrorStats errorStats(const std::vector<double>& distances, const std::vector<double>& weights) {
  ErrorStats s;
  s.samples = distances.size();
  const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
  if (distances.empty() || !(total > 0.0)) {
    return s;
  }
  std::vector<std::size_t> order(distances.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return distances[a] < distances[b]; });
  double sum = 0, cumulative = 0;
  s.p95_m = distances[order.back()];
  bool found = false;
  for (const std::size_t k : order) {
    sum += distances[k] * weights[k];
    cumulative += weights[k];
    if (!found && cumulative >= 0.95 * total) {
      s.p95_m = distances[k];
      found = true;
    }
  }
  s.mean_m = sum / total;
  return s;
}

std::vector<Eigen::Vector3d> groundTruthSamples(const GroundTruth& gt, const MapPoints& points,
                                                const Rigid2D& map_to_gt,
                                                const AccuracyOptions& options) {
  const std::vector<int> labels = pointLabels(gt, points);
  std::vector<Eigen::Vector3d> samples;
  std::unordered_set<std::int64_t> taken;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const GtRectangle* r = labels[i] >= 0 ? gt.surface(labels[i]) : nullptr;
    if (r == nullptr) {
      continue;
    }
    const Eigen::Vector3d p = map_to_gt.apply(points.xyz[i]);
    const auto h = halves(r->corners);
    const Eigen::Vector3d q0 = closestPointOnTriangle(h[0], p);
    const Eigen::Vector3d q1 = closestPointOnTriangle(h[1], p);
    const Eigen::Vector3d q = (q0 - p).squaredNorm() <= (q1 - p).squaredNorm() ? q0 : q1;
    if (taken.insert(cubeKey(q, options.sample_spacing_m)).second) {
      samples.push_back(q);
    }
  }
  return samples;
}

WeightedPoints meshSamples(const std::vector<Triangle3>& triangles, double spacing_m) {
  WeightedPoints out;
  for (const Triangle3& t : triangles) {
    const double longest = std::max({(t.b - t.a).norm(), (t.c - t.b).norm(), (t.a - t.c).norm()});
    const int n = std::max(1, static_cast<int>(std::ceil(longest / spacing_m)));
    const double piece_area = 0.5 * (t.b - t.a).cross(t.c - t.a).norm() / (n * n);
    const Eigen::Vector3d u = (t.b - t.a) / n, v = (t.c - t.a) / n;
    // Pieces of the subdivided triangle: upright (i, j) and inverted ones.
    for (int i = 0; i < n; ++i) {
      for (int j = 0; i + j < n; ++j) {
        out.xyz.push_back(t.a + (i + 1.0 / 3) * u + (j + 1.0 / 3) * v);
        out.weight.push_back(piece_area);
        if (i + j + 1 < n) {
          out.xyz.push_back(t.a + (i + 2.0 / 3) * u + (j + 2.0 / 3) * v);
          out.weight.push_back(piece_area);
        }
      }
    }
  }
  return out;
}

std::vector<Triangle3> groundTruthTriangles(const GroundTruth& gt) {
  std::vector<Triangle3> out;
  for (const GtRectangle& r : gt.surfaces) {
    const auto h = halves(r.corners);
    out.insert(out.end(), h.begin(), h.end());
  }
  return out;
}

MapAccuracy meshAccuracy(const std::vector<Triangle3>& map_triangles, const GroundTruth& gt,
                         const std::vector<Eigen::Vector3d>& gt_samples, const Rigid2D& map_to_gt,
                         const AccuracyOptions& options) {
  std::vector<Triangle3> moved = map_triangles;
  for (Triangle3& t : moved) {
    t = {map_to_gt.apply(t.a), map_to_gt.apply(t.b), map_to_gt.apply(t.c)};
  }
  const WeightedPoints samples = meshSamples(moved, options.mesh_sample_m);
  const TriangleIndex index(std::move(moved), options.index);
  return {gtToMap(gt_samples, index), mapToGt(samples, gt, options)};
}

MapAccuracy pointAccuracy(const std::vector<Eigen::Vector3d>& map_points, const GroundTruth& gt,
                          const std::vector<Eigen::Vector3d>& gt_samples, const Rigid2D& map_to_gt,
                          const AccuracyOptions& options) {
  WeightedPoints samples;
  std::vector<Triangle3> as_triangles;
  for (const Eigen::Vector3d& p : map_points) {
    const Eigen::Vector3d q = map_to_gt.apply(p);
    samples.xyz.push_back(q);
    samples.weight.push_back(1.0);
    as_triangles.push_back({q, q, q});
  }
  const TriangleIndex index(std::move(as_triangles), options.index);
  return {gtToMap(gt_samples, index), mapToGt(samples, gt, options)};
}

}  // namespace pmap::eval
