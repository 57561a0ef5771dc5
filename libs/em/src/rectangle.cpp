#include "pmap/em/rectangle.h"

#include <algorithm>
#include <cmath>

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
