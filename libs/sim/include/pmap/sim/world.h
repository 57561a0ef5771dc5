// The expanded world: every surface as a rectangle (with holes), posters apart
// (texture only, geometrically part of their wall), clutter solids, plus the
// path, sensor and noise options carried over from the world file. Ids are
// unique across surfaces, clutter, posters and people (in that order). A voxel world
// has none of these: it names its OctoMap tree (`octomap`), which the
// simulator reads (voxel_world.h).
#pragma once

#include <string>
#include <vector>

#include "pmap/sim/people.h"
#include "pmap/sim/shapes.h"
#include "pmap/sim/world_spec.h"

namespace pmap::sim {

/// A rectangle of the world. Its normal (rect.normal()) points into the free
/// space the robot is in (for room surfaces: into the room).
struct Surface {
  int id = -1;
  std::string kind;    ///< wall, door, ceiling, floor, jamb, bulkhead, room_wall, ...
  int parent_id = -1;  ///< the wall a door or jamb belongs to, -1 if none
  Rectangle3 rect;
  std::vector<int> poster_indices;  ///< posters on this surface (indices into World::posters)
};

/// A flush poster: its rectangle lies in its wall's plane, u to the right and v
/// up as seen from the free space; image column 0 at u = 0, row 0 at v = length_v.
struct Poster {
  int id = -1;
  int wall_id = -1;
  int wall_index = -1;  ///< index into World::surfaces
  Rectangle3 rect;
  double pixels_per_m = 400.0;
  int width_px = 0;
  int height_px = 0;
};

struct Clutter {
  int id = -1;
  std::string kind;  ///< bin, column, pillar
  ClutterShape shape = ClutterShape::kCylinder;
  VerticalCylinder cylinder;  ///< if shape == kCylinder
  VerticalBox box;            ///< if shape == kBox
};

struct World {
  std::string name;
  std::string source_file;
  std::vector<Surface> surfaces;
  std::vector<Poster> posters;
  std::vector<Clutter> clutter;
  std::vector<WalkingPerson> people;   ///< ids after the posters'
  std::optional<OctomapSpec> octomap;  ///< set: a voxel world
  PathSpec path;
  SensorOptions sensors;
  NoiseOptions noise;
};

}  // namespace pmap::sim
