#include "pmap/refine/surface_params.h"

#include <algorithm>

namespace pmap::refine {

SurfaceParams SurfaceParams::fromRectangle(const em::Rectangle& r) {
  SurfaceParams p;
  p.normal = {r.normal.x(), r.normal.y(), r.normal.z()};
  p.offset = r.offset;
  p.ref_centre = r.centre;
  p.ref_axis = r.axis_u;
  p.bounds = {-r.half_u, r.half_u, -r.half_v, r.half_v};
  return p;
}

em::Rectangle SurfaceParams::toRectangle() const {
  const Frame<double> f = frameOf(normal.data(), &offset, &rotation, ref_centre, ref_axis);
  em::Rectangle r;
  r.normal = f.n;
  r.offset = offset;
  r.axis_u = f.u;
  const double su = 0.5 * (bounds[kUMin] + bounds[kUMax]);
  const double sv = 0.5 * (bounds[kVMin] + bounds[kVMax]);
  r.centre = f.origin + su * f.u + sv * f.v;
  r.half_u = std::max(0.0, 0.5 * (bounds[kUMax] - bounds[kUMin]));
  r.half_v = std::max(0.0, 0.5 * (bounds[kVMax] - bounds[kVMin]));
  return r;
}

std::array<Eigen::Vector3d, 4> cornersOf(const SurfaceParams& p) {
  const Frame<double> f =
      frameOf(p.normal.data(), &p.offset, &p.rotation, p.ref_centre, p.ref_axis);
  return {cornerOf(f, p.bounds.data(), 0), cornerOf(f, p.bounds.data(), 1),
          cornerOf(f, p.bounds.data(), 2), cornerOf(f, p.bounds.data(), 3)};
}

}  // namespace pmap::refine
