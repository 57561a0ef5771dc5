// A planar surface theta_j = <alpha_j, beta_j, gamma_j> (paper eq. 2): unit
// normal alpha, offset beta (plane alpha . x = beta) and a rectangle in that
// plane (gamma: centre, in-plane axis, half extents).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>

namespace pmap::em {

struct Rectangle {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< alpha, unit length
  double offset = 0.0;                                ///< beta (m)
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();   ///< on the plane (m)
  Eigen::Vector3d axis_u = Eigen::Vector3d::UnitX();  ///< unit, in the plane
  double half_u = 0.0;                                ///< half extent along axis_u (m)
  double half_v = 0.0;                                ///< half extent along axis_v (m)
  /// false: the unbounded plane (distance = plane distance everywhere).
  bool bounded = true;

  /// axis_v = normal x axis_u, completing a right-handed in-plane frame.
  Eigen::Vector3d axisV() const { return normal.cross(axis_u); }
  /// Signed distance of p to the plane.
  double planeDistance(const Eigen::Vector3d& p) const { return normal.dot(p) - offset; }
  /// Squared distance to the closest point of the finite rectangle, eq. (5);
  /// plane distance squared when unbounded.
  double squaredDistance(const Eigen::Vector3d& p) const;
  /// The four corners, counter-clockwise seen from the normal's side.
  std::array<Eigen::Vector3d, 4> corners() const;
  double area() const { return 4.0 * half_u * half_v; }
  /// Re-derives centre and axis_u so they lie in the plane (after the plane
  /// changed): centre is projected, axis_u made orthogonal to the normal.
  void reproject();
};

/// Where two rectangles cover the same place: `b` projected orthogonally
/// onto `a`'s plane and clipped to `a`.
struct Overlap {
  double area_m2 = 0.0;  ///< of the clipped projection (0: none, or either unbounded / empty)
  /// Largest distance from b's plane of a point of `a` inside the overlap
  /// (at a vertex of the clipped polygon: the distance is linear in it) (m).
  double max_separation_m = 0.0;
};
Overlap overlapOf(const Rectangle& a, const Rectangle& b);

/// Plane through three points; false if they are (nearly) collinear, judged
/// by the ratio of the triangle's area to its longest side squared.
bool planeFromPoints(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                     Rectangle& out);

}  // namespace pmap::em
