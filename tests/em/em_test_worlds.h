// Synthetic point sets with exact geometry for the EM tests: grids of points
// on rectangles (with a scanner-like neighbour grid), cylinders, noise, a
// corridor swept by a vertical scanner, and helpers to transform and compare
// point sets and maps.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "pmap/em/neighbours.h"
#include "pmap/em/surface.h"

namespace pmap::em::testing {

struct Cloud {
  std::vector<Eigen::Vector3d> points;
  std::vector<GridKey> keys;
  std::vector<std::int32_t> rows;
  Neighbours neighbours() const { return gridNeighbours(keys); }
};

/// 0, 1, ..., n-1.
inline std::vector<std::int32_t> allIndices(std::size_t n) {
  std::vector<std::int32_t> v(n);
  std::iota(v.begin(), v.end(), 0);
  return v;
}

/// Points on the rectangle origin + s*u + t*v (s in [0, su], t in [0, sv])
/// every `step` metres, with Gaussian noise `sigma` along u x v; rows follow
/// s (as scans), cols follow t (as beams). `group` separates sensors.
/// `keep(s, t)` (optional) drops the samples it rejects (an L, a hole).
inline void addPlane(Cloud& c, const Eigen::Vector3d& origin, const Eigen::Vector3d& u,
                     const Eigen::Vector3d& v, double su, double sv, double step, double sigma,
                     std::mt19937_64& rng, std::int32_t group = 0,
                     const std::function<bool(double, double)>& keep = {}) {
  std::normal_distribution<double> noise(0.0, sigma);
  const Eigen::Vector3d n = u.cross(v).normalized();
  const int ns = static_cast<int>(su / step + 1e-9) + 1;
  const int nt = static_cast<int>(sv / step + 1e-9) + 1;
  for (int i = 0; i < ns; ++i) {
    for (int j = 0; j < nt; ++j) {
      if (keep && !keep(i * step, j * step)) {
        continue;
      }
      c.points.push_back(origin + u * (i * step) + v * (j * step) + n * noise(rng));
      c.keys.push_back({group, i, j});
      c.rows.push_back(i);
    }
  }
}

/// Points on a vertical cylinder's half facing -x (a bin seen from one side).
inline void addCylinder(Cloud& c, const Eigen::Vector3d& base, double radius, double height,
                        double step, double sigma, std::mt19937_64& rng, std::int32_t group) {
  std::normal_distribution<double> noise(0.0, sigma);
  const int na = static_cast<int>(M_PI * radius / step) + 1;
  const int nz = static_cast<int>(height / step) + 1;
  for (int i = 0; i < na; ++i) {
    const double a = M_PI / 2 + M_PI * i / (na - 1);
    for (int j = 0; j < nz; ++j) {
      const double r = radius + noise(rng);
      c.points.push_back(base + Eigen::Vector3d(r * std::cos(a), r * std::sin(a), j * step));
      c.keys.push_back({group, i, j});
      c.rows.push_back(i);
    }
  }
}

/// A corridor along +x swept by a vertical scanner: one scan (row) every
/// `step` metres of x; each scan's beams (cols) run up the left wall (y = 0),
/// across the ceiling (z = height) and down the right wall (y = width), one
/// every `step` metres of the profile. A door in the left wall is recessed by
/// `door_depth` (y = -door_depth for x in [door_x0, door_x1], z < door_height).
/// Scan and beam positions are jittered by up to +-`jitter` x step (a robot's
/// uneven speed): with an exact lattice, three beams of one scan fix the
/// plane x = const exactly and the next scan lies exactly 2.5 sigma = 5 cm
/// from it, the seeding's growth threshold, so rounding alone would decide.
struct CorridorSpec {
  double length = 6.0;
  double width = 2.0;
  double height = 2.5;
  double step = 0.05;
  double sigma = 0.02;
  double door_depth = 0.0;
  double door_x0 = 2.0;
  double door_x1 = 3.2;
  double door_height = 2.0;
  bool ceiling = true;
  double jitter = 0.1;
};

inline void addCorridor(Cloud& c, const CorridorSpec& s, std::mt19937_64& rng,
                        std::int32_t group = 0) {
  std::normal_distribution<double> noise(0.0, s.sigma);
  std::uniform_real_distribution<double> shake(-s.jitter * s.step, s.jitter * s.step);
  const int rows = static_cast<int>(s.length / s.step + 1e-9) + 1;
  const int up = static_cast<int>(s.height / s.step + 1e-9);     // left wall beams
  const int across = static_cast<int>(s.width / s.step + 1e-9);  // ceiling beams
  for (int i = 0; i < rows; ++i) {
    const double x = std::clamp(i * s.step + shake(rng), 0.0, s.length);
    for (int j = 0; j <= 2 * up + across; ++j) {
      const double t = std::max(0.0, j * s.step + shake(rng));  // along the profile
      Eigen::Vector3d p;
      if (j < up) {  // left wall, normal y
        const double z = std::min(t, s.height);
        const bool door = x >= s.door_x0 && x <= s.door_x1 && z < s.door_height;
        p = {x, (door ? -s.door_depth : 0.0) + noise(rng), z};
      } else if (j <= up + across) {  // ceiling, normal z
        if (!s.ceiling) {
          continue;
        }
        p = {x, std::clamp(t - up * s.step, 0.0, s.width), s.height + noise(rng)};
      } else {  // right wall, going down
        p = {x, s.width + noise(rng), std::max(0.0, s.height - (t - (up + across) * s.step))};
      }
      c.points.push_back(p);
      c.keys.push_back({group, i, j});
      c.rows.push_back(i);
    }
  }
}

/// A rigid motion applied to every point.
inline std::vector<Eigen::Vector3d> transformed(const std::vector<Eigen::Vector3d>& points,
                                                const Eigen::Isometry3d& T) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(points.size());
  for (const auto& p : points) {
    out.push_back(T * p);
  }
  return out;
}

/// A random rotation (uniform quaternion) and a translation of up to `reach` m.
inline Eigen::Isometry3d randomMotion(std::mt19937_64& rng, double reach) {
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_real_distribution<double> t(-reach, reach);
  const Eigen::Quaterniond q = Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = q.toRotationMatrix();
  T.translation() = Eigen::Vector3d(t(rng), t(rng), t(rng));
  return T;
}

/// Angle (deg) between the lines of two normals (sign ignored).
inline double lineAngleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::min(1.0, std::abs(a.dot(b)))) * 180.0 / M_PI;
}

/// Index of the surface whose plane best matches the plane n . x = d, -1 if
/// none has its normal within `max_deg` (either sign) and its centre within
/// `max_offset_m` of that plane. The error is measured at the surface, not as
/// a difference of offsets beta: a tilt of 0.001 deg changes the offset of a
/// wall 1e5 m from the origin by almost 2 m.
inline int matchPlane(const std::vector<Surface>& surfaces, const Eigen::Vector3d& n, double d,
                      double max_deg, double max_offset_m) {
  int best = -1;
  double best_err = max_offset_m;
  for (std::size_t j = 0; j < surfaces.size(); ++j) {
    const Rectangle& r = surfaces[j].rect;
    const double err = std::abs(n.normalized().dot(r.centre) - d);
    if (lineAngleDeg(r.normal, n) <= max_deg && err <= best_err) {
      best = static_cast<int>(j);
      best_err = err;
    }
  }
  return best;
}

/// One line per surface (normal, offset, centre, extents, support), for
/// failure messages.
inline std::string describe(const std::vector<Surface>& surfaces) {
  std::ostringstream o;
  for (const Surface& s : surfaces) {
    o << "\n  n (" << s.rect.normal.transpose() << ") d " << s.rect.offset << " centre ("
      << s.rect.centre.transpose() << ") half " << s.rect.half_u << " x " << s.rect.half_v
      << " support " << s.support;
  }
  return o.str();
}

}  // namespace pmap::em::testing
