#include "pmap/sim/ray_caster.h"

#include <cmath>

namespace pmap::sim {

RayCaster::RayCaster(const World& world) : world_(world) {
  for (const Surface& s : world.surfaces) {
    const double r = 0.5 * std::hypot(s.rect.length_u, s.rect.length_v);
    spheres_.push_back(Sphere{s.rect.centre(), r});
    glass_.push_back(s.kind == "glass" ? 1 : 0);
  }
  for (const Clutter& c : world.clutter) {
    if (c.shape == ClutterShape::kCylinder) {
      const VerticalCylinder& y = c.cylinder;
      const double h = 0.5 * (y.z_max_m - y.z_min_m);
      const Eigen::Vector3d centre(y.centre.x(), y.centre.y(), 0.5 * (y.z_min_m + y.z_max_m));
      spheres_.push_back(Sphere{centre, std::hypot(y.radius_m, h)});
    } else {
      const VerticalBox& b = c.box;
      const double h = 0.5 * (b.z_max_m - b.z_min_m);
      const Eigen::Vector3d centre(b.centre.x(), b.centre.y(), 0.5 * (b.z_min_m + b.z_max_m));
      spheres_.push_back(Sphere{centre, std::sqrt(b.half_size_m.squaredNorm() + h * h)});
    }
  }
}

std::vector<int> RayCaster::selectNearPoint(const Eigen::Vector3d& point, double range_m) const {
  std::vector<int> out;
  for (std::size_t i = 0; i < spheres_.size(); ++i) {
    if ((spheres_[i].centre - point).norm() <= range_m + spheres_[i].radius) {
      out.push_back(static_cast<int>(i));
    }
  }
  return out;
}

std::vector<int> RayCaster::selectNearPlane(const Eigen::Vector3d& point,
                                            const Eigen::Vector3d& normal, double range_m) const {
  std::vector<int> out;
  for (std::size_t i = 0; i < spheres_.size(); ++i) {
    const Eigen::Vector3d d = spheres_[i].centre - point;
    if (std::abs(d.dot(normal)) <= spheres_[i].radius && d.norm() <= range_m + spheres_[i].radius) {
      out.push_back(static_cast<int>(i));
    }
  }
  return out;
}

std::optional<SceneHit> RayCaster::castOne(int object, const Eigen::Vector3d& origin,
                                           const Eigen::Vector3d& dir, double t_min,
                                           double t_max) const {
  const int n_surfaces = static_cast<int>(world_.surfaces.size());
  std::optional<ShapeHit> hit;
  SceneHit out;
  if (object < n_surfaces) {
    const Surface& s = world_.surfaces[static_cast<std::size_t>(object)];
    hit = intersectRectangle(s.rect, origin, dir, t_min, t_max);
    out.id = s.id;
    out.type = ObjectType::kSurface;
    out.index = object;
  } else {
    const Clutter& c = world_.clutter[static_cast<std::size_t>(object - n_surfaces)];
    hit = c.shape == ClutterShape::kCylinder
              ? intersectCylinder(c.cylinder, origin, dir, t_min, t_max)
              : intersectBox(c.box, origin, dir, t_min, t_max);
    out.id = c.id;
    out.type = ObjectType::kClutter;
    out.index = object - n_surfaces;
  }
  if (!hit) {
    return std::nullopt;
  }
  out.t = hit->t;
  out.normal = hit->normal;
  out.local = hit->local;
  return out;
}

std::optional<SceneHit> RayCaster::cast(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                                        double t_max, const std::vector<int>* candidates,
                                        double t_min) const {
  std::optional<SceneHit> best;
  auto consider = [&](int object) {
    const double limit = best ? best->t : t_max;
    if (auto h = castOne(object, origin, dir, t_min, limit)) {
      if (!best || h->t < best->t) {
        best = *h;
      }
    }
  };
  if (candidates != nullptr) {
    for (const int object : *candidates) {
      consider(object);
    }
  } else {
    for (std::size_t i = 0; i < spheres_.size(); ++i) {
      consider(static_cast<int>(i));
    }
  }
  return best;
}

}  // namespace pmap::sim
