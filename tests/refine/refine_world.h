// Small synthetic scenes for the refinement tests: a corridor corner (a wall
// under a ceiling), noisy points on them, and EM-like rectangles that stop
// short of the seams.
#pragma once

#include <Eigen/Core>
#include <random>
#include <vector>

#include "pmap/em/surface.h"
#include "pmap/refine/boundary_refiner.h"

namespace pmap::refine::testing {

/// The rectangle of plane n . x = offset through centre, axis u, half extents.
inline em::Rectangle rectangle(const Eigen::Vector3d& n, const Eigen::Vector3d& centre,
                               const Eigen::Vector3d& u, double half_u, double half_v) {
  em::Rectangle r;
  r.normal = n.normalized();
  r.centre = centre;
  r.offset = r.normal.dot(centre);
  r.axis_u = u.normalized();
  r.half_u = half_u;
  r.half_v = half_v;
  return r;
}

/// Points on rectangle r (a grid of `step_m`), with Gaussian noise sigma along
/// the normal.
inline void addPoints(const em::Rectangle& r, double step_m, double sigma_m, std::mt19937& rng,
                      std::vector<Eigen::Vector3d>& points) {
  std::normal_distribution<double> noise(0.0, sigma_m);
  const Eigen::Vector3d v = r.axisV();
  for (double s = -r.half_u; s <= r.half_u + 1e-9; s += step_m) {
    for (double t = -r.half_v; t <= r.half_v + 1e-9; t += step_m) {
      points.push_back(r.centre + s * r.axis_u + t * v + noise(rng) * r.normal);
    }
  }
}

struct Scene {
  std::vector<Eigen::Vector3d> points;
  std::vector<em::Surface> surfaces;
  std::vector<std::vector<SurfaceSample>> samples;
};

/// Each surface's samples: the points generated from it, weight 1.
inline void appendSurface(const em::Rectangle& truth, const em::Rectangle& estimate, double sigma_m,
                          std::mt19937& rng, Scene& scene) {
  const std::size_t first = scene.points.size();
  addPoints(truth, 0.05, sigma_m, rng, scene.points);
  std::vector<SurfaceSample> samples;
  for (std::size_t i = first; i < scene.points.size(); ++i) {
    samples.push_back({static_cast<std::int32_t>(i), 1.0});
  }
  scene.samples.push_back(samples);
  scene.surfaces.push_back({estimate, static_cast<std::int32_t>(scene.surfaces.size()),
                            static_cast<std::int32_t>(samples.size()), false});
}

/// A wall (plane y = 0, x in [0, 4], z in [0, 2.7]) under a ceiling (z = 2.7,
/// x in [0, 4], y in [0, 2]): the laser saw the wall up to 2.62 m and the
/// ceiling from y = 0.06 m, so the EM's rectangles stop short of the seam.
inline Scene wallUnderCeiling(double sigma_m, unsigned seed = 7) {
  std::mt19937 rng(seed);
  Scene scene;
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX();
  appendSurface(rectangle(Eigen::Vector3d::UnitY(), {2.0, 0.0, 1.31}, x, 2.0, 1.31),
                rectangle(Eigen::Vector3d::UnitY(), {2.0, 0.0, 1.31}, x, 2.0, 1.31), sigma_m, rng,
                scene);
  appendSurface(rectangle(-Eigen::Vector3d::UnitZ(), {2.0, 1.03, 2.7}, x, 2.0, 0.97),
                rectangle(-Eigen::Vector3d::UnitZ(), {2.0, 1.03, 2.7}, x, 2.0, 0.97), sigma_m, rng,
                scene);
  return scene;
}

}  // namespace pmap::refine::testing
