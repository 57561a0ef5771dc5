// Doors, doorways and posters on corridor walls. An opening of width W and
// height H centred at s = c becomes: a hole in the wall, a left and a right
// jamb and a head ("jamb") and a threshold ("floor") spanning the reveal depth
// behind the wall plane, and then either a door leaf at that depth or a room
// box behind a wall of that thickness.
#include <cmath>

#include "corridor_layout.h"
#include "pmap/common/error.h"

namespace pmap::sim::detail {
namespace {

struct Placement {
  const LegFrame* leg = nullptr;
  int wall_index = -1;
  double sigma = 1.0;   ///< +1 left wall, -1 right wall
  double y_wall = 0.0;  ///< lateral offset of the wall plane
};

[[noreturn]] void fail(const CorridorLayout& c, const std::string& where, const std::string& what) {
  throw ConfigError(c.file + ": " + where + ": " + what);
}

bool overlaps(const HoleRange& a, const HoleRange& b) {
  return a.u0 < b.u1 && b.u0 < a.u1 && a.v0 < b.v1 && b.v0 < a.v1;
}

/// Local (u, v) box of the wall area s in [s0, s1], z in [z0, z1].
HoleRange localBox(const Rectangle3& wall, const Placement& p, double s0, double s1, double z0,
                   double z1) {
  const Eigen::Vector2d a = wall.toLocal(p.leg->point(s0, p.y_wall, z0));
  const Eigen::Vector2d b = wall.toLocal(p.leg->point(s1, p.y_wall, z1));
  return HoleRange{std::min(a.x(), b.x()), std::max(a.x(), b.x()), std::min(a.y(), b.y()),
                   std::max(a.y(), b.y())};
}

/// Finds the wall piece holding s in [s0, s1], z in [z0, z1] and claims that area.
Placement place(const CorridorLayout& c, SceneAssembler& scene, const std::string& where, int leg,
                Side side, double s0, double s1, double z0, double z1, bool is_hole) {
  const auto it = c.pieces.find({leg, static_cast<int>(side)});
  if (it != c.pieces.end()) {
    for (const WallPiece& piece : it->second) {
      if (s0 < piece.s_lo - 1e-9 || s1 > piece.s_hi + 1e-9) {
        continue;
      }
      if (z1 > piece.height_m - 1e-9) {
        fail(c, where,
             "reaches the top of its wall (wall height " + std::to_string(piece.height_m) + " m)");
      }
      Placement p{&c.legs[static_cast<std::size_t>(leg)], piece.surface_index,
                  static_cast<double>(static_cast<int>(side)), 0.0};
      p.y_wall = p.sigma * 0.5 * c.width_m;
      Surface& wall = scene.surface(piece.surface_index);
      const HoleRange box = localBox(wall.rect, p, s0, s1, z0, z1);
      for (const HoleRange& other : scene.occupied(piece.surface_index)) {
        if (overlaps(box, other)) {
          fail(c, where, "overlaps another door, doorway or poster on the same wall");
        }
      }
      scene.occupied(piece.surface_index).push_back(box);
      if (is_hole) {
        wall.rect.holes.push_back(box);
      }
      return p;
    }
  }
  fail(c, where,
       "does not fit on one wall rectangle of leg " + std::to_string(leg) +
           " (check centre_m and width_m against the leg length and its corners)");
}

/// Hole, two side jambs and a head across `depth` behind the wall plane.
Placement addOpening(const CorridorLayout& c, SceneAssembler& scene, const std::string& where,
                     int leg, Side side, double centre, double width, double height, double depth) {
  const double s0 = centre - 0.5 * width;
  const double s1 = centre + 0.5 * width;
  const Placement p = place(c, scene, where, leg, side, s0, s1, 0.0, height, true);
  const LegFrame& f = *p.leg;
  const double y1 = p.y_wall + p.sigma * depth;
  const Eigen::Vector3d inside = f.point(centre, p.y_wall + 0.5 * p.sigma * depth, 0.5 * height);
  for (const double s : {s0, s1}) {
    scene.addSurface("jamb",
                     Rectangle3::facing(f.point(s, p.y_wall, 0.0), f.point(s, y1, 0.0),
                                        f.point(s, p.y_wall, height), inside),
                     p.wall_index);
  }
  scene.addSurface("jamb",
                   Rectangle3::facing(f.point(s0, p.y_wall, height), f.point(s1, p.y_wall, height),
                                      f.point(s0, y1, height), inside),
                   p.wall_index);
  // The threshold closes the reveal at floor level (below the structure laser).
  scene.addSurface("floor",
                   Rectangle3::facing(f.point(s0, p.y_wall, 0.0), f.point(s1, p.y_wall, 0.0),
                                      f.point(s0, y1, 0.0), inside),
                   p.wall_index);
  return p;
}

void checkPositive(const CorridorLayout& c, const std::string& where, double centre, double width) {
  if (centre - 0.5 * width < -1e-9) {
    fail(c, where, "starts before the beginning of its leg");
  }
}

}  // namespace

void addDoor(const CorridorLayout& c, const DoorSpec& d, SceneAssembler& scene) {
  checkPositive(c, d.where, d.centre_m, d.width_m);
  const Placement p =
      addOpening(c, scene, d.where, d.leg, d.side, d.centre_m, d.width_m, d.height_m, d.recess_m);
  const LegFrame& f = *p.leg;
  const double y = p.y_wall + p.sigma * d.recess_m;
  const double s0 = d.centre_m - 0.5 * d.width_m;
  const double s1 = d.centre_m + 0.5 * d.width_m;
  scene.addSurface(
      "door",
      Rectangle3::facing(f.point(s0, y, 0.0), f.point(s1, y, 0.0), f.point(s0, y, d.height_m),
                         f.point(d.centre_m, 0.0, 0.5 * d.height_m)),
      scene.surface(p.wall_index).id);
}

void addDoorway(const CorridorLayout& c, const DoorwaySpec& d, SceneAssembler& scene) {
  checkPositive(c, d.where, d.centre_m, d.width_m);
  const RoomSpec& room = d.room;
  if (std::abs(room.offset_m) + 0.5 * d.width_m > 0.5 * room.width_m + 1e-9) {
    fail(c, d.where + ".room", "the doorway does not open into the room (width_m/offset_m)");
  }
  if (room.height_m < d.height_m) {
    fail(c, d.where + ".room", "height_m is lower than the doorway");
  }
  const Placement p = addOpening(c, scene, d.where, d.leg, d.side, d.centre_m, d.width_m,
                                 d.height_m, d.wall_thickness_m);
  const LegFrame& f = *p.leg;
  const double y0 = p.y_wall + p.sigma * d.wall_thickness_m;
  const double y1 = y0 + p.sigma * room.depth_m;
  const double s0 = d.centre_m + room.offset_m - 0.5 * room.width_m;
  const double s1 = d.centre_m + room.offset_m + 0.5 * room.width_m;
  const double h = room.height_m;
  const Eigen::Vector3d inside = f.point(0.5 * (s0 + s1), 0.5 * (y0 + y1), 0.5 * h);
  auto add = [&](const char* kind, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                 const Eigen::Vector3d& e) {
    return scene.addSurface(kind, Rectangle3::facing(a, b, e, inside));
  };
  const int front = add("room_wall", f.point(s0, y0, 0), f.point(s1, y0, 0), f.point(s0, y0, h));
  Surface& fw = scene.surface(front);
  const Eigen::Vector2d a = fw.rect.toLocal(f.point(d.centre_m - 0.5 * d.width_m, y0, 0.0));
  const Eigen::Vector2d b = fw.rect.toLocal(f.point(d.centre_m + 0.5 * d.width_m, y0, d.height_m));
  fw.rect.holes.push_back(HoleRange{std::min(a.x(), b.x()), std::max(a.x(), b.x()),
                                    std::min(a.y(), b.y()), std::max(a.y(), b.y())});
  add("room_wall", f.point(s0, y1, 0), f.point(s1, y1, 0), f.point(s0, y1, h));
  add("room_wall", f.point(s0, y0, 0), f.point(s0, y1, 0), f.point(s0, y0, h));
  add("room_wall", f.point(s1, y0, 0), f.point(s1, y1, 0), f.point(s1, y0, h));
  add("room_floor", f.point(s0, y0, 0), f.point(s1, y0, 0), f.point(s0, y1, 0));
  add("room_ceiling", f.point(s0, y0, h), f.point(s1, y0, h), f.point(s0, y1, h));
}

void addPoster(const CorridorLayout& c, const PosterSpec& ps, SceneAssembler& scene) {
  checkPositive(c, ps.where, ps.centre_m, ps.width_m);
  const double s0 = ps.centre_m - 0.5 * ps.width_m;
  const double s1 = ps.centre_m + 0.5 * ps.width_m;
  const double z0 = ps.bottom_m;
  const double z1 = ps.bottom_m + ps.height_m;
  const Placement p = place(c, scene, ps.where, ps.leg, ps.side, s0, s1, z0, z1, false);
  const LegFrame& f = *p.leg;
  Poster poster;
  poster.wall_index = p.wall_index;
  poster.rect = Rectangle3::facing(f.point(s0, p.y_wall, z0), f.point(s1, p.y_wall, z0),
                                   f.point(s0, p.y_wall, z1), f.point(ps.centre_m, 0.0, z0));
  poster.pixels_per_m = ps.pixels_per_m;
  poster.width_px = std::max(1, static_cast<int>(std::lround(ps.width_m * ps.pixels_per_m)));
  poster.height_px = std::max(1, static_cast<int>(std::lround(ps.height_m * ps.pixels_per_m)));
  World& w = scene.world();
  scene.surface(p.wall_index).poster_indices.push_back(static_cast<int>(w.posters.size()));
  w.posters.push_back(poster);
}

}  // namespace pmap::sim::detail
