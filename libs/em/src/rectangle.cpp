#include "pmap/em/rectangle.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace pmap::em {

// Eq. (5): inside the rectangle's projection, the distance is the plane
// distance |alpha . z - beta|; outside, the distance to the boundary (edge or
// corner). Both are the distance to the closest point of the rectangle.
double Rectangle::squaredDistance(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d d = p - centre;
  const double h = normal.dot(d);
  if (!bounded) {
    return h * h;
  }
  const Eigen::Vector3d v = axisV();
  const double a = axis_u.dot(d);
  const double b = v.dot(d);
  const double da = std::max(std::abs(a) - half_u, 0.0);
  const double db = std::max(std::abs(b) - half_v, 0.0);
  return h * h + da * da + db * db;
}

std::array<Eigen::Vector3d, 4> Rectangle::corners() const {
  const Eigen::Vector3d u = axis_u * half_u;
  const Eigen::Vector3d v = axisV() * half_v;
  return {centre - u - v, centre + u - v, centre + u + v, centre - u + v};
}

void Rectangle::reproject() {
  centre -= normal * planeDistance(centre);
  Eigen::Vector3d u = axis_u - normal * normal.dot(axis_u);
  if (u.squaredNorm() < 1e-12) {
    // axis_u was (nearly) along the normal: pick any in-plane direction.
    u = normal.unitOrthogonal();
  }
  axis_u = u.normalized();
}

namespace {

using Polygon = std::vector<Eigen::Vector2d>;

// Sutherland-Hodgman: the part of convex `poly` where coordinate `axis`
// times `sign` is at most `limit`.
Polygon clipHalfPlane(const Polygon& poly, int axis, double sign, double limit) {
  Polygon out;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const Eigen::Vector2d& p = poly[k];
    const Eigen::Vector2d& q = poly[(k + 1) % poly.size()];
    const double fp = sign * p(axis) - limit;
    const double fq = sign * q(axis) - limit;
    if (fp <= 0.0) {
      out.push_back(p);
    }
    if ((fp < 0.0 && fq > 0.0) || (fp > 0.0 && fq < 0.0)) {
      out.push_back(p + (q - p) * (fp / (fp - fq)));
    }
  }
  return out;
}

double polygonArea(const Polygon& poly) {
  double twice = 0.0;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const Eigen::Vector2d& p = poly[k];
    const Eigen::Vector2d& q = poly[(k + 1) % poly.size()];
    twice += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * std::abs(twice);
}

}  // namespace

Overlap overlapOf(const Rectangle& a, const Rectangle& b) {
  Overlap out;
  if (!a.bounded || !b.bounded || a.area() <= 0.0 || b.area() <= 0.0) {
    return out;
  }
  const Eigen::Vector3d v = a.axisV();
  Polygon poly;
  for (const Eigen::Vector3d& c : b.corners()) {
    const Eigen::Vector3d d = c - a.centre;
    poly.emplace_back(a.axis_u.dot(d), v.dot(d));
  }
  // b's projected corners form a parallelogram (convex); clip it to a's box.
  for (int axis = 0; axis < 2 && !poly.empty(); ++axis) {
    const double half = axis == 0 ? a.half_u : a.half_v;
    poly = clipHalfPlane(poly, axis, 1.0, half);
    if (!poly.empty()) {
      poly = clipHalfPlane(poly, axis, -1.0, half);
    }
  }
  if (poly.size() < 3) {
    return out;
  }
  out.area_m2 = polygonArea(poly);
  for (const Eigen::Vector2d& q : poly) {
    const Eigen::Vector3d p = a.centre + a.axis_u * q.x() + v * q.y();
    out.max_separation_m = std::max(out.max_separation_m, std::abs(b.planeDistance(p)));
  }
  return out;
}

bool planeFromPoints(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                     Rectangle& out) {
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double longest2 =
      std::max({(b - a).squaredNorm(), (c - a).squaredNorm(), (c - b).squaredNorm()});
  // |n| = 2 x area; a well-shaped triangle has area ~ longest^2; reject slivers.
  if (longest2 <= 0.0 || n.norm() < 0.05 * longest2) {
    return false;
  }
  out.normal = n.normalized();
  out.centre = (a + b + c) / 3.0;
  out.offset = out.normal.dot(out.centre);
  out.axis_u = (b - a).normalized();
  out.reproject();
  out.half_u = 0.0;
  out.half_v = 0.0;
  return true;
}

}  // namespace pmap::em
