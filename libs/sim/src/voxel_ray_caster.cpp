#include "pmap/sim/voxel_ray_caster.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace pmap::sim {
namespace {

/// The part [t0, t1] of [0, t_max] inside the box [lo, hi] (slab method);
/// false if the ray misses it.
bool clipToBox(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Eigen::Vector3d& lo,
               const Eigen::Vector3d& hi, double& t0, double& t1) {
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0.0) {
      if (o[a] < lo[a] || o[a] >= hi[a]) {
        return false;
      }
      continue;
    }
    double ta = (lo[a] - o[a]) / d[a];
    double tb = (hi[a] - o[a]) / d[a];
    if (ta > tb) {
      std::swap(ta, tb);
    }
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t0 <= t1;
}

/// The voxel the ray is in just after the point p (on a voxel boundary, the
/// one on the side the ray goes to), clamped to [lo, hi].
int startIndex(double p, double d, double res, int lo, int hi) {
  const double s = p / res;
  double f = std::floor(s);
  if (d < 0.0 && s == f) {
    f -= 1.0;
  }
  return static_cast<int>(std::clamp(f, static_cast<double>(lo), static_cast<double>(hi)));
}

}  // namespace

std::optional<VoxelHit> VoxelRayCaster::cast(const Eigen::Vector3d& origin,
                                             const Eigen::Vector3d& dir, double t_max) const {
  if (world_.empty() || !origin.allFinite() || !dir.allFinite() || !(t_max >= 0.0)) {
    return std::nullopt;
  }
  const double res = world_.resolution_m();
  const Eigen::Vector3i& vmin = world_.minIndex();
  const Eigen::Vector3i& vmax = world_.maxIndex();
  const Eigen::Vector3d lo = vmin.cast<double>() * res;
  const Eigen::Vector3d hi = (vmax.cast<double>().array() + 1.0).matrix() * res;
  double t0 = 0.0;
  double t1 = t_max;
  if (!clipToBox(origin, dir, lo, hi, t0, t1)) {
    return std::nullopt;
  }
  const Eigen::Vector3d p = origin + t0 * dir;
  Eigen::Vector3i v;
  Eigen::Vector3i step;
  for (int a = 0; a < 3; ++a) {
    v[a] = startIndex(p[a], dir[a], res, vmin[a], vmax[a]);
    step[a] = dir[a] > 0.0 ? 1 : (dir[a] < 0.0 ? -1 : 0);
  }
  // One voxel per iteration, in the order the ray enters them; consecutive
  // voxels mostly share a brick, whose mask is looked up once.
  std::uint64_t brick = ~std::uint64_t{0};
  std::uint64_t mask = 0;
  double t = t0;
  for (;;) {
    const std::uint64_t key = VoxelWorld::brickKey(v);
    if (key != brick) {
      brick = key;
      mask = world_.brickMask(key);
    }
    if (((mask >> VoxelWorld::brickBit(v)) & 1u) != 0) {
      return VoxelHit{t, v};
    }
    int axis = -1;
    double t_next = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
      if (step[a] == 0) {
        continue;
      }
      // Recomputed from the boundary each time: no accumulated rounding.
      const double boundary = (v[a] + (step[a] > 0 ? 1 : 0)) * res;
      const double ta = (boundary - origin[a]) / dir[a];
      if (ta < t_next) {
        t_next = ta;
        axis = a;
      }
    }
    if (axis < 0 || t_next > t1) {
      return std::nullopt;
    }
    v[axis] += step[axis];
    if (v[axis] < vmin[axis] || v[axis] > vmax[axis]) {
      return std::nullopt;
    }
    t = std::max(t, t_next);
  }
}

}  // namespace pmap::sim
