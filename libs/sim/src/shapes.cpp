#include "pmap/sim/shapes.h"

#include <Eigen/Geometry>
#include <cassert>
#include <cmath>
#include <limits>
#include <utility>

namespace pmap::sim {
namespace {

constexpr double kParallelEpsilon = 1e-12;
constexpr double kEdgeEpsilon_m = 1e-9;

void keepNearest(std::optional<ShapeHit>& best, const ShapeHit& candidate) {
  if (!best || candidate.t < best->t) {
    best = candidate;
  }
}

}  // namespace

std::array<Eigen::Vector3d, 4> Rectangle3::corners() const {
  return {at(0.0, 0.0), at(length_u, 0.0), at(length_u, length_v), at(0.0, length_v)};
}

std::array<Eigen::Vector3d, 4> Rectangle3::holeCorners(const HoleRange& h) const {
  return {at(h.u0, h.v0), at(h.u1, h.v0), at(h.u1, h.v1), at(h.u0, h.v1)};
}

Eigen::Vector2d Rectangle3::toLocal(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d d = p - origin;
  return Eigen::Vector2d(d.dot(axis_u), d.dot(axis_v));
}

bool Rectangle3::containsLocal(double u, double v) const {
  if (u < -kEdgeEpsilon_m || u > length_u + kEdgeEpsilon_m || v < -kEdgeEpsilon_m ||
      v > length_v + kEdgeEpsilon_m) {
    return false;
  }
  for (const HoleRange& h : holes) {
    if (u > h.u0 && u < h.u1 && v > h.v0 && v < h.v1) {
      return false;
    }
  }
  return true;
}

Rectangle3 Rectangle3::fromCorners(const Eigen::Vector3d& c0, const Eigen::Vector3d& c1,
                                   const Eigen::Vector3d& c3) {
  Rectangle3 r;
  r.origin = c0;
  r.length_u = (c1 - c0).norm();
  r.length_v = (c3 - c0).norm();
  assert(r.length_u > 0.0 && r.length_v > 0.0);
  r.axis_u = (c1 - c0) / r.length_u;
  r.axis_v = (c3 - c0) / r.length_v;
  assert(std::abs(r.axis_u.dot(r.axis_v)) < 1e-6);
  return r;
}

Rectangle3 Rectangle3::facing(const Eigen::Vector3d& c0, const Eigen::Vector3d& c1,
                              const Eigen::Vector3d& c3, const Eigen::Vector3d& free_space_point) {
  const Rectangle3 r = fromCorners(c0, c1, c3);
  if (r.normal().dot(free_space_point - c0) >= 0.0) {
    return r;
  }
  return fromCorners(c1, c0, c1 + (c3 - c0));
}

std::optional<ShapeHit> intersectRectangle(const Rectangle3& rect, const Eigen::Vector3d& origin,
                                           const Eigen::Vector3d& dir, double t_min, double t_max) {
  const Eigen::Vector3d n = rect.normal();
  const double denom = n.dot(dir);
  if (std::abs(denom) < kParallelEpsilon * dir.norm()) {
    return std::nullopt;
  }
  const double t = n.dot(rect.origin - origin) / denom;
  if (!(t > t_min && t <= t_max)) {
    return std::nullopt;
  }
  const Eigen::Vector2d local = rect.toLocal(origin + t * dir);
  if (!rect.containsLocal(local.x(), local.y())) {
    return std::nullopt;
  }
  return ShapeHit{t, n, local};
}

std::optional<ShapeHit> intersectCylinder(const VerticalCylinder& cyl,
                                          const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                                          double t_min, double t_max) {
  std::optional<ShapeHit> best;
  const double ox = origin.x() - cyl.centre.x();
  const double oy = origin.y() - cyl.centre.y();
  const double a = dir.x() * dir.x() + dir.y() * dir.y();
  const double b = 2.0 * (ox * dir.x() + oy * dir.y());
  const double c = ox * ox + oy * oy - cyl.radius_m * cyl.radius_m;
  const double disc = b * b - 4.0 * a * c;
  if (a > kParallelEpsilon && disc >= 0.0) {
    const double sq = std::sqrt(disc);
    for (const double t : {(-b - sq) / (2.0 * a), (-b + sq) / (2.0 * a)}) {
      const double z = origin.z() + t * dir.z();
      if (t > t_min && t <= t_max && z >= cyl.z_min_m && z <= cyl.z_max_m) {
        const double x = ox + t * dir.x();
        const double y = oy + t * dir.y();
        const Eigen::Vector3d n(x / cyl.radius_m, y / cyl.radius_m, 0.0);
        keepNearest(best, ShapeHit{t, n, Eigen::Vector2d(std::atan2(y, x) * cyl.radius_m, z)});
        break;  // the smaller valid root is the nearer one
      }
    }
  }
  if (std::abs(dir.z()) > kParallelEpsilon) {
    for (const double zc : {cyl.z_min_m, cyl.z_max_m}) {
      const double t = (zc - origin.z()) / dir.z();
      const double x = ox + t * dir.x();
      const double y = oy + t * dir.y();
      if (t > t_min && t <= t_max && x * x + y * y <= cyl.radius_m * cyl.radius_m) {
        const Eigen::Vector3d n(0.0, 0.0, zc == cyl.z_max_m ? 1.0 : -1.0);
        keepNearest(best, ShapeHit{t, n, Eigen::Vector2d(x, y)});
      }
    }
  }
  return best;
}

std::optional<ShapeHit> intersectBox(const VerticalBox& box, const Eigen::Vector3d& origin,
                                     const Eigen::Vector3d& dir, double t_min, double t_max) {
  // Slab method in the box frame (rotated by -yaw about the box centre).
  const double c = std::cos(box.yaw_rad);
  const double s = std::sin(box.yaw_rad);
  const double px = origin.x() - box.centre.x();
  const double py = origin.y() - box.centre.y();
  const Eigen::Vector3d o(c * px + s * py, -s * px + c * py, origin.z());
  const Eigen::Vector3d d(c * dir.x() + s * dir.y(), -s * dir.x() + c * dir.y(), dir.z());
  const Eigen::Vector3d lo(-box.half_size_m.x(), -box.half_size_m.y(), box.z_min_m);
  const Eigen::Vector3d hi(box.half_size_m.x(), box.half_size_m.y(), box.z_max_m);
  double t_near = -std::numeric_limits<double>::infinity();
  double t_far = std::numeric_limits<double>::infinity();
  int axis_near = -1;
  int axis_far = -1;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(d[k]) < kParallelEpsilon) {
      if (o[k] < lo[k] || o[k] > hi[k]) {
        return std::nullopt;
      }
      continue;
    }
    double t0 = (lo[k] - o[k]) / d[k];
    double t1 = (hi[k] - o[k]) / d[k];
    if (t0 > t1) {
      std::swap(t0, t1);
    }
    if (t0 > t_near) {
      t_near = t0;
      axis_near = k;
    }
    if (t1 < t_far) {
      t_far = t1;
      axis_far = k;
    }
  }
  if (t_near > t_far) {
    return std::nullopt;
  }
  const bool from_outside = t_near > t_min;
  const double t = from_outside ? t_near : t_far;
  const int axis = from_outside ? axis_near : axis_far;
  if (!(t > t_min && t <= t_max) || axis < 0) {
    return std::nullopt;
  }
  const Eigen::Vector3d p = o + t * d;
  Eigen::Vector3d n_box = Eigen::Vector3d::Zero();
  n_box[axis] = (p[axis] > 0.5 * (lo[axis] + hi[axis])) ? 1.0 : -1.0;
  const Eigen::Vector3d n(c * n_box.x() - s * n_box.y(), s * n_box.x() + c * n_box.y(), n_box.z());
  const Eigen::Vector2d local =
      axis == 2 ? Eigen::Vector2d(p.x(), p.y()) : Eigen::Vector2d(p[1 - axis] + p[axis], p.z());
  return ShapeHit{t, n, local};
}

}  // namespace pmap::sim
