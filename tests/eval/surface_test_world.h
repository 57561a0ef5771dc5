// A small synthetic world for the surface evaluation tests: ground-truth
// rectangles, mapped points (all in structure scan 0, one beam each) with
// their ground-truth labels, and map surfaces built from the ground truth.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <string>
#include <vector>

#include "pmap/eval/ground_truth.h"
#include "pmap/eval/map_files.h"
#include "pmap/eval/reference_surfaces.h"
#include "pmap/eval/surface_files.h"

namespace pmap::eval::testing {

/// Rectangle c0, c0 + u, c0 + u + v, c0 + v.
inline Rectangle rectangle(const Eigen::Vector3d& c0, const Eigen::Vector3d& u,
                           const Eigen::Vector3d& v) {
  return {c0, c0 + u, c0 + u + v, c0 + v};
}

class SurfaceTestWorld {
 public:
  SurfaceTestWorld() { gt.hits[0] = {}; }

  /// A ground-truth rectangle; normal (c1 - c0) x (c3 - c0) as in gt.json.
  void addRectangle(int id, const std::string& kind, const Rectangle& corners) {
    GtRectangle r;
    r.id = id;
    r.kind = kind;
    r.corners = corners;
    r.normal = (corners[1] - corners[0]).cross(corners[3] - corners[0]).normalized();
    gt.surfaces.push_back(r);
  }

  void addCylinder(int id, const Eigen::Vector2d& centre, double radius) {
    gt.cylinders.push_back({id, "bin", centre, radius, 0.0, 1.0});
  }

  /// A mapped point whose beam's true ray hit `label`, assigned to `surface`.
  void addPoint(const Eigen::Vector3d& xyz, int label, int surface) {
    gt.hits[0].push_back(label);
    points.xyz.push_back(xyz);
    points.scan.push_back(0);
    points.beam.push_back(static_cast<int>(gt.hits[0].size()) - 1);
    points.surface.push_back(surface);
  }

  /// `n` beams of another scan that hit `label` without a mapped point.
  void addHitsWithoutPoints(int label, int n) {
    auto& beams = gt.hits[static_cast<std::int64_t>(gt.hits.size())];
    beams.insert(beams.end(), static_cast<std::size_t>(n), label);
  }

  /// A grid of nu x nv points spanning the rectangle `id` between fractions
  /// [a0, a1] x [b0, b1] of its edges (edges included), labelled `id` and
  /// assigned to map surface `surface`.
  void addGrid(int id, int surface, int nu, int nv, double a0 = 0, double a1 = 1, double b0 = 0,
               double b1 = 1) {
    const GtRectangle& r = *gt.surface(id);
    const Eigen::Vector3d u = r.corners[1] - r.corners[0];
    const Eigen::Vector3d v = r.corners[3] - r.corners[0];
    for (int i = 0; i < nu; ++i) {
      for (int j = 0; j < nv; ++j) {
        const double a = a0 + (a1 - a0) * i / (nu - 1);
        const double b = b0 + (b1 - b0) * j / (nv - 1);
        addPoint(r.corners[0] + a * u + b * v, id, surface);
      }
    }
  }

  /// The map surface a perfect mapper would write for ground-truth `gt_id`.
  MapSurface perfectSurface(int gt_id, int map_id) const {
    const GtRectangle& r = *gt.surface(gt_id);
    MapSurface s;
    s.id = map_id;
    s.normal = r.normal;
    s.offset_m = r.normal.dot(r.corners[0]);
    s.corners = r.corners;
    return s;
  }

  GroundTruth gt;
  MapPoints points;
  std::vector<MapSurface> surfaces;
};

/// Map surface through the rectangle `corners` (normal from their order).
inline MapSurface surfaceFromCorners(int map_id, const Rectangle& corners) {
  MapSurface s;
  s.id = map_id;
  s.normal = (corners[1] - corners[0]).cross(corners[3] - corners[0]).normalized();
  s.offset_m = s.normal.dot(corners[0]);
  s.corners = corners;
  return s;
}

}  // namespace pmap::eval::testing
