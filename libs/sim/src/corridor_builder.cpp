// Corridor shell expansion. For leg i (s along the leg, y to the left):
//  - the corner square around each turn waypoint belongs to the earlier leg, so
//    floors and flat ceilings cover s in [0 or w/2, L or L + w/2];
//  - at a turn the outer wall runs to the outer corner (s = L + w/2, or starts
//    at -w/2), the inner wall stops at the inner corner (L - w/2, or w/2);
//  - a sloped leg keeps its tilted ceiling off the corner squares: these get a
//    flat ceiling at height_m, the walls beside them height_m, and a vertical
//    "bulkhead" closes the step between the two ceilings.
#include <Eigen/Geometry>
#include <cmath>

#include "corridor_layout.h"
#include "pmap/common/error.h"

namespace pmap::sim::detail {
namespace {

constexpr double kTurnTolerance = 1e-6;

int turnSign(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x() > 0.0 ? 1 : -1;
}

void fail(const CorridorLayout& c, const std::string& what) {
  throw ConfigError(c.file + ": " + c.where + ": " + what);
}

std::vector<LegFrame> makeLegs(const CorridorSpec& spec, const CorridorLayout& layout) {
  std::vector<LegFrame> legs;
  const std::size_t n = spec.centreline.size() - 1;
  for (std::size_t i = 0; i < n; ++i) {
    LegFrame leg;
    leg.start = spec.centreline[i];
    const Eigen::Vector2d delta = spec.centreline[i + 1] - spec.centreline[i];
    leg.length_m = delta.norm();
    if (leg.length_m < 1e-6) {
      fail(layout, "centreline waypoints " + std::to_string(i) + " and " + std::to_string(i + 1) +
                       " coincide");
    }
    leg.dir = delta / leg.length_m;
    leg.left = Eigen::Vector2d(-leg.dir.y(), leg.dir.x());
    leg.slope_tan = std::tan(spec.legs[i].ceiling_slope_deg * M_PI / 180.0);
    if (i > 0) {
      const LegFrame& prev = legs.back();
      if (std::abs(prev.dir.dot(leg.dir)) > kTurnTolerance) {
        fail(layout, "the turn at centreline waypoint " + std::to_string(i) +
                         " is not +-90 degrees (only right-angle turns are supported)");
      }
      leg.turn_in = turnSign(prev.dir, leg.dir);
      legs.back().turn_out = leg.turn_in;
    }
    legs.push_back(leg);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double needed = layout.width_m * (0.5 * (i > 0) + 0.5 * (i + 1 < n));
    if (legs[i].length_m < needed + 1e-9) {
      fail(layout, "leg " + std::to_string(i) + " is shorter than its corner squares (" +
                       std::to_string(needed) + " m)");
    }
  }
  return legs;
}

/// s-range of the wall of `side` on leg i: outer walls run to the corners.
std::pair<double, double> wallRange(const LegFrame& leg, Side side, double w) {
  const int sigma = static_cast<int>(side);
  const double s0 = leg.turn_in == 0 ? 0.0 : (sigma == -leg.turn_in ? -0.5 * w : 0.5 * w);
  const double s1 = leg.turn_out == 0 ? leg.length_m
                                      : (sigma == -leg.turn_out ? leg.length_m + 0.5 * w
                                                                : leg.length_m - 0.5 * w);
  return {s0, s1};
}

/// s-range of the leg proper (without the corner squares).
std::pair<double, double> coreRange(const LegFrame& leg, double w) {
  return {leg.turn_in == 0 ? 0.0 : 0.5 * w,
          leg.turn_out == 0 ? leg.length_m : leg.length_m - 0.5 * w};
}

/// s-range of floor and flat ceiling: the corner square after the leg is included.
std::pair<double, double> floorRange(const LegFrame& leg, double w) {
  return {leg.turn_in == 0 ? 0.0 : 0.5 * w,
          leg.turn_out == 0 ? leg.length_m : leg.length_m + 0.5 * w};
}

void addWallPiece(CorridorLayout& c, int leg_index, Side side, double s_lo, double s_hi,
                  double height, SceneAssembler& scene) {
  if (s_hi - s_lo < 1e-9) {
    return;
  }
  const LegFrame& leg = c.legs[static_cast<std::size_t>(leg_index)];
  const double y = static_cast<int>(side) * 0.5 * c.width_m;
  const Rectangle3 rect = Rectangle3::facing(leg.point(s_lo, y, 0.0), leg.point(s_hi, y, 0.0),
                                             leg.point(s_lo, y, height),
                                             leg.point(0.5 * (s_lo + s_hi), 0.0, 0.5 * height));
  const int index = scene.addSurface("wall", rect);
  c.pieces[{leg_index, static_cast<int>(side)}].push_back(WallPiece{index, s_lo, s_hi, height});
}

void addWalls(CorridorLayout& c, int i, SceneAssembler& scene) {
  const LegFrame& leg = c.legs[static_cast<std::size_t>(i)];
  const auto [core0, core1] = coreRange(leg, c.width_m);
  for (const Side side : {Side::kLeft, Side::kRight}) {
    const auto [s0, s1] = wallRange(leg, side, c.width_m);
    const double h = c.wallHeight(i, side);
    if (leg.slope_tan == 0.0) {
      addWallPiece(c, i, side, s0, s1, h, scene);
      continue;
    }
    addWallPiece(c, i, side, s0, core0, c.height_m, scene);  // beside the corner square
    addWallPiece(c, i, side, std::max(s0, core0), std::min(s1, core1), h, scene);
    addWallPiece(c, i, side, core1, s1, c.height_m, scene);
  }
}

void addHorizontal(const CorridorLayout& c, const LegFrame& leg, const std::string& kind,
                   double s_lo, double s_hi, double z, SceneAssembler& scene) {
  const double w = 0.5 * c.width_m;
  const Rectangle3 rect =
      Rectangle3::facing(leg.point(s_lo, -w, z), leg.point(s_hi, -w, z), leg.point(s_lo, w, z),
                         leg.point(0.5 * (s_lo + s_hi), 0.0, 0.5 * c.height_m));
  scene.addSurface(kind, rect);
}

void addCrossWall(const CorridorLayout& c, const LegFrame& leg, const std::string& kind, double s,
                  double z0, double z1, double inward, SceneAssembler& scene) {
  const double w = 0.5 * c.width_m;
  const Rectangle3 rect =
      Rectangle3::facing(leg.point(s, -w, z0), leg.point(s, w, z0), leg.point(s, -w, z1),
                         leg.point(s + inward, 0.0, 0.5 * (z0 + z1)));
  scene.addSurface(kind, rect);
}

void addFloorAndCeiling(const CorridorLayout& c, int i, SceneAssembler& scene) {
  const LegFrame& leg = c.legs[static_cast<std::size_t>(i)];
  const auto [f0, f1] = floorRange(leg, c.width_m);
  addHorizontal(c, leg, "floor", f0, f1, 0.0, scene);
  if (leg.slope_tan == 0.0) {
    addHorizontal(c, leg, "ceiling", f0, f1, c.height_m, scene);
    return;
  }
  const auto [core0, core1] = coreRange(leg, c.width_m);
  const double w = 0.5 * c.width_m;
  const Rectangle3 sloped = Rectangle3::facing(
      leg.point(core0, -w, c.ceilingAt(i, -w)), leg.point(core1, -w, c.ceilingAt(i, -w)),
      leg.point(core0, w, c.ceilingAt(i, w)),
      leg.point(0.5 * (core0 + core1), 0.0, 0.5 * c.height_m));
  scene.addSurface("ceiling", sloped);
  const double top = c.height_m + c.width_m * std::abs(leg.slope_tan);
  if (leg.turn_in != 0) {
    addCrossWall(c, leg, "bulkhead", core0, c.height_m, top, 0.5, scene);
  }
  if (leg.turn_out != 0) {
    addHorizontal(c, leg, "ceiling", core1, f1, c.height_m, scene);  // the flat corner square
    addCrossWall(c, leg, "bulkhead", core1, c.height_m, top, -0.5, scene);
  }
}

}  // namespace

Eigen::Vector3d LegFrame::point(double s, double y, double z) const {
  const Eigen::Vector2d p = start + s * dir + y * left;
  return Eigen::Vector3d(p.x(), p.y(), z);
}

int SceneAssembler::addSurface(const std::string& kind, const Rectangle3& rect, int parent_id) {
  Surface s;
  s.id = static_cast<int>(world_.surfaces.size());
  s.kind = kind;
  s.parent_id = parent_id;
  s.rect = rect;
  world_.surfaces.push_back(s);
  return s.id;
}

double CorridorLayout::ceilingAt(int leg, double y) const {
  const double t = legs[static_cast<std::size_t>(leg)].slope_tan;
  return height_m + std::abs(t) * (0.5 * width_m + (t >= 0.0 ? y : -y));
}

double CorridorLayout::wallHeight(int leg, Side side) const {
  return ceilingAt(leg, static_cast<int>(side) * 0.5 * width_m);
}

CorridorLayout buildCorridorShell(const CorridorSpec& spec, const std::string& file,
                                  SceneAssembler& scene) {
  CorridorLayout c;
  c.file = file;
  c.where = spec.where;
  c.width_m = spec.width_m;
  c.height_m = spec.height_m;
  c.legs = makeLegs(spec, c);
  const int n = static_cast<int>(c.legs.size());
  for (int i = 0; i < n; ++i) {
    addWalls(c, i, scene);
    addFloorAndCeiling(c, i, scene);
  }
  const auto endHeight = [&](int i) {
    return std::max(c.wallHeight(i, Side::kLeft), c.wallHeight(i, Side::kRight));
  };
  if (spec.closed_start) {
    addCrossWall(c, c.legs.front(), "wall", 0.0, 0.0, endHeight(0), 0.5, scene);
  }
  if (spec.closed_end) {
    const LegFrame& last = c.legs.back();
    addCrossWall(c, last, "wall", last.length_m, 0.0, endHeight(n - 1), -0.5, scene);
  }
  return c;
}

}  // namespace pmap::sim::detail
