#include "pmap/refine/openings.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pmap::refine {
namespace {

constexpr double kBandShare = 0.8;      // the part of an edge whose neighbours count
constexpr double kMinOuterShare = 0.5;  // only points in the door's outer half count
constexpr std::size_t kMinWallPoints = 3;

// The side of its plane a surface's measurements were taken from: +1, -1,
// or 0 when it cannot be told.
int viewerSide(const em::Rectangle& r, const std::vector<std::int32_t>& members,
               const std::vector<Eigen::Vector3d>& viewpoints) {
  double sum = 0;
  for (const std::int32_t i : members) {
    sum += r.planeDistance(viewpoints[static_cast<std::size_t>(i)]);
  }
  return sum > 0 ? 1 : (sum < 0 ? -1 : 0);
}

// How far door d lies behind wall w as seen from w's viewpoints (m); NaN when
// d is no door of w (not parallel, not inside its rectangle, not behind it).
double recess(const em::Rectangle& d, const em::Rectangle& w, int w_side, double max_angle_deg) {
  if (w_side == 0 || d.area() >= w.area() ||
      std::abs(d.normal.dot(w.normal)) < std::cos(max_angle_deg * M_PI / 180.0)) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  const Eigen::Vector3d c = d.centre - w.centre;
  if (std::abs(c.dot(w.axis_u)) > w.half_u || std::abs(c.dot(w.axisV())) > w.half_v) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  const double depth = -w_side * w.planeDistance(d.centre);
  return depth > 0 ? depth : std::numeric_limits<double>::quiet_NaN();
}

struct Projected {
  std::vector<Eigen::Vector2d> door, wall;  ///< (u, v) in the door's frame
};

Projected project(const std::vector<Eigen::Vector3d>& points, const em::Rectangle& d,
                  const std::vector<std::int32_t>& door, const std::vector<std::int32_t>& wall,
                  double reach) {
  Projected out;
  const Eigen::Vector3d v = d.axisV();
  auto add = [&](const std::vector<std::int32_t>& ids, std::vector<Eigen::Vector2d>& to) {
    for (const std::int32_t i : ids) {
      const Eigen::Vector3d q = points[static_cast<std::size_t>(i)] - d.centre;
      const Eigen::Vector2d uv(q.dot(d.axis_u), q.dot(v));
      if (std::abs(uv.x()) <= d.half_u + reach && std::abs(uv.y()) <= d.half_v + reach) {
        to.push_back(uv);
      }
    }
  };
  add(door, out.door);
  add(wall, out.wall);
  return out;
}

// The opening's edge on the side `sign` of `axis` (0: u, 1: v), in the
// door's frame, or NaN. Beside the edge's middle, the door's and the wall's
// points along the axis are separated by a threshold that misplaces about
// the fewest of them (door points beyond it, wall points before it; within
// 2 % of them); the edge is halfway across the widest such gap. Where
// nothing crosses (the door's last scan, then the wall's first) that is the
// midpoint of the two; where the reveal's points mix at the edge (the
// lintel's underside, shared by the door and the wall within noise) it is
// the middle of the mix, not its end.
double openingEdge(const Projected& p, int axis, int sign, double half_along, double half_across,
                   double reach) {
  const int across = 1 - axis;
  std::vector<std::pair<double, bool>> line;  // (coordinate outwards, is a wall point)
  std::size_t walls = 0;
  auto collect = [&](const std::vector<Eigen::Vector2d>& pts, bool wall) {
    for (const Eigen::Vector2d& q : pts) {
      const double a = sign * q[axis];
      if (std::abs(q[across]) <= kBandShare * half_across && a > kMinOuterShare * half_along &&
          a <= half_along + reach) {
        line.emplace_back(a, wall);
        walls += wall ? 1 : 0;
      }
    }
  };
  collect(p.door, false);
  collect(p.wall, true);
  if (walls < kMinWallPoints || walls == line.size()) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  std::sort(line.begin(), line.end());
  // errors[k]: points misplaced by a split after k (wall points at 0..k,
  // door points after k).
  std::vector<std::size_t> errors(line.size() - 1);
  std::size_t walls_before = 0, doors_after = line.size() - walls;
  for (std::size_t k = 0; k + 1 < line.size(); ++k) {
    if (line[k].second) {
      ++walls_before;
    } else {
      --doors_after;
    }
    errors[k] = walls_before + doors_after;
  }
  // The widest gap among the splits within a few points of the fewest
  // misplaced (a stray point on either side does not pin the edge).
  const std::size_t slack = std::max<std::size_t>(1, line.size() / 50);
  const std::size_t allowed = *std::min_element(errors.begin(), errors.end()) + slack;
  double best_gap = -1, edge = 0;
  for (std::size_t k = 0; k + 1 < line.size(); ++k) {
    const double gap = line[k + 1].first - line[k].first;
    if (errors[k] <= allowed && gap > best_gap) {
      best_gap = gap;
      edge = 0.5 * (line[k].first + line[k + 1].first);
    }
  }
  return std::abs(edge - half_along) <= reach ? edge : std::numeric_limits<double>::quiet_NaN();
}

// Moves door d's edges onto the opening of wall w; returns the edges moved.
Opening align(const std::vector<Eigen::Vector3d>& points, const std::vector<std::int32_t>& door,
              const std::vector<std::int32_t>& wall, double reach, em::Surface& d) {
  const Projected p = project(points, d.rect, door, wall, reach);
  Opening o;
  double lo[2] = {-d.rect.half_u, -d.rect.half_v};
  double hi[2] = {d.rect.half_u, d.rect.half_v};
  for (int axis = 0; axis < 2; ++axis) {
    const double half_along = axis == 0 ? d.rect.half_u : d.rect.half_v;
    const double half_across = axis == 0 ? d.rect.half_v : d.rect.half_u;
    for (const int sign : {-1, 1}) {
      const double edge = openingEdge(p, axis, sign, half_along, half_across, reach);
      if (std::isnan(edge)) {
        continue;
      }
      (sign > 0 ? hi[axis] : lo[axis]) = sign * edge;
      o.max_move_m = std::max(o.max_move_m, std::abs(edge - half_along));
      ++o.edges;
    }
  }
  if (o.edges > 0 && hi[0] > lo[0] && hi[1] > lo[1]) {
    d.rect.centre +=
        d.rect.axis_u * (0.5 * (lo[0] + hi[0])) + d.rect.axisV() * (0.5 * (lo[1] + hi[1]));
    d.rect.half_u = 0.5 * (hi[0] - lo[0]);
    d.rect.half_v = 0.5 * (hi[1] - lo[1]);
  } else {
    o.edges = 0;
  }
  return o;
}

}  // namespace

OpeningResult alignToOpenings(const std::vector<Eigen::Vector3d>& points,
                              const std::vector<std::int32_t>& assignment,
                              const std::vector<Eigen::Vector3d>& viewpoints,
                              const RefineOptions& options, std::vector<em::Surface>& surfaces) {
  OpeningResult result;
  if (viewpoints.size() != points.size() || assignment.size() != points.size()) {
    return result;
  }
  const std::size_t J = surfaces.size();
  std::vector<std::vector<std::int32_t>> members(J);
  for (std::size_t i = 0; i < assignment.size(); ++i) {
    if (assignment[i] >= 0 && static_cast<std::size_t>(assignment[i]) < J) {
      members[static_cast<std::size_t>(assignment[i])].push_back(static_cast<std::int32_t>(i));
    }
  }
  std::vector<int> side(J);
  for (std::size_t j = 0; j < J; ++j) {
    side[j] = viewerSide(surfaces[j].rect, members[j], viewpoints);
  }
  const std::vector<em::Surface> before = surfaces;  // walls as the EM / solve left them
  for (std::size_t d = 0; d < J; ++d) {
    std::size_t wall = J;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t w = 0; w < J; ++w) {
      const double depth =
          w == d ? std::numeric_limits<double>::quiet_NaN()
                 : recess(before[d].rect, before[w].rect, side[w], options.opening_max_angle_deg);
      if (depth <= options.seam_distance_m && depth < best) {
        best = depth;
        wall = w;
      }
    }
    if (wall == J) {
      continue;
    }
    Opening o = align(points, members[d], members[wall], options.seam_distance_m, surfaces[d]);
    if (o.edges > 0) {
      o.door_id = surfaces[d].id;
      o.wall_id = surfaces[wall].id;
      result.openings.push_back(o);
    }
  }
  return result;
}

}  // namespace pmap::refine
