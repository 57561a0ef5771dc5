#include "pmap/eval/seam_gaps.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace pmap::eval {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

struct Plane {
  Eigen::Vector3d n;
  double offset;
  double distance(const Eigen::Vector3d& p) const { return n.dot(p) - offset; }
};

Plane planeOf(const GtRectangle& r) {
  return {r.normal, r.normal.dot(r.corners[0])};
}

// Length of the part of segment p0-p1 whose points, projected onto the
// plane of r, lie within `slack` of the rectangle r (sampled every 1 cm).
double besideLength(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const GtRectangle& r,
                    double slack) {
  const Plane plane = planeOf(r);
  const double length = (p1 - p0).norm();
  const int samples = std::max(1, static_cast<int>(std::ceil(length / 0.01)));
  int beside = 0;
  for (int i = 0; i < samples; ++i) {
    const Eigen::Vector3d p = p0 + (p1 - p0) * ((i + 0.5) / samples);
    beside += distanceToRectangle(r.corners, p - plane.n * plane.distance(p)) <= slack ? 1 : 0;
  }
  return length * beside / samples;
}

// Signed in-plane distance from p (on the plane with normal n_a through
// centre_a) to the line where it meets plane b: > 0 when p lies on the same
// side of plane b as centre_a.
double signedGap(const Eigen::Vector3d& n_a, const Eigen::Vector3d& centre_a, const Plane& b,
                 const Eigen::Vector3d& p) {
  const double sine = n_a.cross(b.n).norm();
  const double side = b.distance(centre_a) >= 0 ? 1.0 : -1.0;
  return side * b.distance(p) / sine;
}

Eigen::Vector3d centreOf(const std::array<Eigen::Vector3d, 4>& c) {
  return 0.25 * (c[0] + c[1] + c[2] + c[3]);
}

// The shared part of a ground-truth seam as an interval of the line
// origin + t dir: the edge's extent intersected with the other rectangle's.
std::array<double, 2> sharedInterval(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                                     double edge_length, const GtRectangle& other) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const Eigen::Vector3d& c : other.corners) {
    lo = std::min(lo, dir.dot(c - origin));
    hi = std::max(hi, dir.dot(c - origin));
  }
  lo = std::max(lo, 0.0);
  hi = std::min(hi, edge_length);
  return hi > lo ? std::array<double, 2>{lo, hi} : std::array<double, 2>{0.0, edge_length};
}

// The point of segment p0-p1 whose projection on the line is at t (clamped
// to the segment).
Eigen::Vector3d pointAt(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                        const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double t) {
  const double t0 = dir.dot(p0 - origin);
  const double t1 = dir.dot(p1 - origin);
  const double f = std::abs(t1 - t0) < 1e-12 ? 0.0 : std::clamp((t - t0) / (t1 - t0), 0.0, 1.0);
  return p0 + f * (p1 - p0);
}

}  // namespace

std::vector<GtSeam> groundTruthSeams(const GroundTruth& gt, const std::vector<int>& ids,
                                     const SeamOptions& options) {
  const double max_cos = std::cos(options.min_angle_deg * kDegToRad);
  std::vector<GtSeam> seams;
  for (const int a : ids) {
    const GtRectangle* ra = gt.surface(a);
    for (const int b : ids) {
      const GtRectangle* rb = gt.surface(b);
      if (ra == nullptr || rb == nullptr || a == b ||
          std::abs(ra->normal.dot(rb->normal)) > max_cos) {
        continue;
      }
      const Plane pb = planeOf(*rb);
      for (int e = 0; e < 4; ++e) {
        const Eigen::Vector3d& p0 = ra->corners[static_cast<std::size_t>(e)];
        const Eigen::Vector3d& p1 = ra->corners[static_cast<std::size_t>((e + 1) % 4)];
        if (std::abs(pb.distance(p0)) <= options.on_plane_m &&
            std::abs(pb.distance(p1)) <= options.on_plane_m &&
            besideLength(p0, p1, *rb, options.on_plane_m) >= options.min_shared_m) {
          seams.push_back({a, b, e});
        }
      }
    }
  }
  return seams;
}

std::vector<GtSeam> openingEdges(const GroundTruth& gt, const std::vector<int>& ids,
                                 const SeamOptions& options) {
  const double min_cos = std::cos(options.min_angle_deg * kDegToRad);
  std::vector<GtSeam> out;
  for (const int id : ids) {
    const GtRectangle* door = gt.surface(id);
    const GtRectangle* wall = door == nullptr ? nullptr : gt.surface(door->parent);
    if (wall == nullptr || std::abs(door->normal.dot(wall->normal)) < min_cos) {
      continue;
    }
    const Plane plane = planeOf(*wall);
    const Eigen::Vector3d u = (wall->corners[1] - wall->corners[0]).normalized();
    const Eigen::Vector3d v = (wall->corners[3] - wall->corners[0]).normalized();
    const double lu = (wall->corners[1] - wall->corners[0]).norm();
    const double lv = (wall->corners[3] - wall->corners[0]).norm();
    for (int e = 0; e < 4; ++e) {
      const Eigen::Vector3d mid = 0.5 * (door->corners[static_cast<std::size_t>(e)] +
                                         door->corners[static_cast<std::size_t>((e + 1) % 4)]);
      const Eigen::Vector3d q = mid - plane.n * plane.distance(mid) - wall->corners[0];
      const double s = q.dot(u), t = q.dot(v), m = options.on_plane_m;
      if (s > m && s < lu - m && t > m && t < lv - m) {
        out.push_back({id, door->parent, e});
      }
    }
  }
  return out;
}

std::array<Eigen::Vector3d, 4> closedReference(const GtRectangle& rect,
                                               const std::array<Eigen::Vector3d, 4>& clipped,
                                               const std::vector<GtSeam>& seams, double reach_m) {
  std::array<Eigen::Vector3d, 4> out = clipped;
  for (const GtSeam& seam : seams) {
    if (seam.gt_id != rect.id) {
      continue;
    }
    const auto k = static_cast<std::size_t>(seam.edge);
    const Eigen::Vector3d& g0 = rect.corners[k];
    const Eigen::Vector3d dir = (rect.corners[(k + 1) % 4] - g0).normalized();
    const Eigen::Vector3d off = out[k] - g0;
    const Eigen::Vector3d to_edge = -(off - dir * dir.dot(off));  // perpendicular, in the plane
    if (to_edge.norm() <= reach_m) {
      out[k] += to_edge;
      out[(k + 1) % 4] += to_edge;
    }
  }
  return out;
}

std::vector<SeamSide> seamSides(const GroundTruth& gt,
                                const std::vector<std::pair<int, MapSurface>>& primary,
                                const SeamOptions& options) {
  std::map<int, const MapSurface*> by_gt;
  std::vector<int> ids;
  for (const auto& [id, s] : primary) {
    by_gt[id] = &s;
    ids.push_back(id);
  }
  const double min_along = std::cos(30.0 * kDegToRad);
  std::vector<SeamSide> sides;
  for (const GtSeam& seam : groundTruthSeams(gt, ids, options)) {
    const GtRectangle& g = *gt.surface(seam.gt_id);
    const Eigen::Vector3d g0 = g.corners[static_cast<std::size_t>(seam.edge)];
    const Eigen::Vector3d g1 = g.corners[static_cast<std::size_t>((seam.edge + 1) % 4)];
    const Eigen::Vector3d line = (g1 - g0).normalized();
    const std::array<double, 2> shared =
        sharedInterval(g0, line, (g1 - g0).norm(), *gt.surface(seam.gt_other));
    const MapSurface& m = *by_gt[seam.gt_id];
    const MapSurface& o = *by_gt[seam.gt_other];
    if (m.id == o.id || m.normal.cross(o.normal).norm() < 1e-9) {
      continue;
    }
    double best = std::numeric_limits<double>::infinity();
    SeamSide side{seam.gt_id, seam.gt_other, m.id, o.id, 0.0};
    for (std::size_t e = 0; e < 4; ++e) {
      const Eigen::Vector3d& p0 = m.corners[e];
      const Eigen::Vector3d& p1 = m.corners[(e + 1) % 4];
      if (std::abs((p1 - p0).normalized().dot(line)) < min_along) {
        continue;
      }
      const Eigen::Vector3d mid = 0.5 * (p0 + p1) - g0;
      const double to_line = (mid - line * line.dot(mid)).norm();
      if (to_line < best) {
        best = to_line;
        const Plane other{o.normal, o.offset_m};
        const Eigen::Vector3d centre = centreOf(m.corners);
        side.gap_m =
            0.5 * (signedGap(m.normal, centre, other, pointAt(p0, p1, g0, line, shared[0])) +
                   signedGap(m.normal, centre, other, pointAt(p0, p1, g0, line, shared[1])));
      }
    }
    if (std::isfinite(best)) {
      sides.push_back(side);
    }
  }
  return sides;
}

}  // namespace pmap::eval
