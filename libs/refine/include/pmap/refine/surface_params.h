// A surface as the solver sees it: plane theta = <alpha, beta> (eq. 2) with the
// unit normal on the sphere, and the rectangle gamma as four bounds in an
// in-plane frame that follows the plane. The frame is derived from the EM's
// rectangle (reference centre c0 and axis u0): u = u0 projected into the
// plane and turned by `rotation` about the normal, v = n x u, origin = c0
// projected onto the plane. The rectangle is
// {origin + s u + t v : u_min <= s <= u_max, v_min <= t <= v_max}.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cmath>

#include "pmap/em/rectangle.h"

namespace pmap::refine {

/// Indices into SurfaceParams::bounds.
enum Bound { kUMin = 0, kUMax = 1, kVMin = 2, kVMax = 3 };

struct SurfaceParams {
  std::array<double, 3> normal{0, 0, 1};                 ///< alpha (unit; SphereManifold)
  double offset = 0;                                     ///< beta (m)
  double rotation = 0;                                   ///< in-plane turn of the frame (rad)
  std::array<double, 4> bounds{0, 0, 0, 0};              ///< u_min, u_max, v_min, v_max (m)
  Eigen::Vector3d ref_centre = Eigen::Vector3d::Zero();  ///< c0 (constant)
  Eigen::Vector3d ref_axis = Eigen::Vector3d::UnitX();   ///< u0 (constant)

  /// The parameters reproducing `r` exactly (rotation 0, bounds = +-half).
  static SurfaceParams fromRectangle(const em::Rectangle& r);
  /// Back to the EM's representation (unit normal, centred frame).
  em::Rectangle toRectangle() const;
  Eigen::Vector3d normalVector() const { return {normal[0], normal[1], normal[2]}; }
};

/// The in-plane frame of a surface, for doubles and ceres::Jet alike.
template <typename T>
struct Frame {
  Eigen::Matrix<T, 3, 1> n, origin, u, v;
};

template <typename T>
Frame<T> frameOf(const T* normal, const T* offset, const T* rotation, const Eigen::Vector3d& c0,
                 const Eigen::Vector3d& u0) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  using V = Eigen::Matrix<T, 3, 1>;
  Frame<T> f;
  f.n = V(normal[0], normal[1], normal[2]);
  const V c = c0.cast<T>();
  const V a = u0.cast<T>();
  V up = a - f.n * f.n.dot(a);
  up /= sqrt(up.squaredNorm());
  const V vp = f.n.cross(up);
  f.u = cos(rotation[0]) * up + sin(rotation[0]) * vp;
  f.v = f.n.cross(f.u);
  f.origin = c - f.n * (f.n.dot(c) - offset[0]);
  return f;
}

/// Corner k (0..3, counter-clockwise seen from the normal's side):
/// (u_min, v_min), (u_max, v_min), (u_max, v_max), (u_min, v_max).
/// Edge k joins corner k and corner (k + 1) % 4.
template <typename T>
Eigen::Matrix<T, 3, 1> cornerOf(const Frame<T>& f, const T* bounds, int k) {
  const T s = (k == 1 || k == 2) ? bounds[kUMax] : bounds[kUMin];
  const T t = (k >= 2) ? bounds[kVMax] : bounds[kVMin];
  return f.origin + s * f.u + t * f.v;
}

/// The point of edge k at coordinate `along` on it (s along u for the
/// u-edges 0 (v = v_min) and 2 (v = v_max), t along v for the v-edges 1
/// (u = u_max) and 3 (u = u_min)).
template <typename T>
Eigen::Matrix<T, 3, 1> edgePoint(const Frame<T>& f, const T* bounds, int k, double along) {
  const T a(along);
  switch (k) {
    case 0:
      return f.origin + a * f.u + bounds[kVMin] * f.v;
    case 1:
      return f.origin + bounds[kUMax] * f.u + a * f.v;
    case 2:
      return f.origin + a * f.u + bounds[kVMax] * f.v;
    default:
      return f.origin + bounds[kUMin] * f.u + a * f.v;
  }
}

/// Corners of a surface's current parameters (doubles).
std::array<Eigen::Vector3d, 4> cornersOf(const SurfaceParams& p);

}  // namespace pmap::refine
