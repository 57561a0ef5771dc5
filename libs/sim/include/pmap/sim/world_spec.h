// A world as written in a world file (config/worlds/*.json): corridors with
// their doors, doorways to rooms and posters, clutter, free rectangles (or,
// instead of all these, an OctoMap tree whose occupied voxels are the
// building), the robot's path and the sensor/noise blocks. buildWorld() expands it into
// rectangles (world.h). Every element keeps `where`, its JSON path, so that
// geometric errors found while expanding can name file and key.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "pmap/sim/sensor_options.h"

namespace pmap::sim {

/// Which wall of a corridor leg, seen in the leg's direction of travel.
enum class Side { kLeft = 1, kRight = -1 };

/// A door leaf set `recess_m` behind an opening in a corridor wall.
struct DoorSpec {
  std::string where;
  int leg = 0;  ///< 0-based leg index
  Side side = Side::kLeft;
  double centre_m = 0.0;  ///< along the leg, from its start waypoint, metres
  double width_m = 0.9;
  double height_m = 2.0;
  double recess_m = 0.10;  ///< depth of the reveal behind the wall plane, metres
};

/// A room box behind a doorway: width along the leg, depth away from it.
struct RoomSpec {
  double width_m = 3.0;
  double depth_m = 3.0;
  double height_m = 2.6;
  double offset_m = 0.0;  ///< room centre minus doorway centre, along the leg, metres
};

/// An open doorway (no leaf) through a wall `wall_thickness_m` thick into a room.
struct DoorwaySpec {
  std::string where;
  int leg = 0;
  Side side = Side::kLeft;
  double centre_m = 0.0;
  double width_m = 1.0;
  double height_m = 2.1;
  double wall_thickness_m = 0.10;
  RoomSpec room;
};

/// A flush poster on a corridor wall (texture only).
struct PosterSpec {
  std::string where;
  int leg = 0;
  Side side = Side::kLeft;
  double centre_m = 0.0;  ///< along the leg, metres
  double bottom_m = 1.2;  ///< height of the lower edge, metres
  double width_m = 1.0;
  double height_m = 0.7;
  double pixels_per_m = 400.0;  ///< resolution of the generated poster image
};

/// Per-leg options.
struct LegSpec {
  /// Tilts the ceiling across the corridor: positive raises the left side.
  /// The lower side stays at the corridor's height_m.
  double ceiling_slope_deg = 0.0;
};

/// A corridor along a centreline polyline with +-90 degree turns.
struct CorridorSpec {
  std::string where;
  std::string name;
  std::vector<Eigen::Vector2d> centreline;  ///< waypoints, metres (>= 2)
  double width_m = 2.2;
  double height_m = 2.7;
  bool closed_start = true;   ///< end wall at the first waypoint
  bool closed_end = true;     ///< end wall at the last waypoint
  std::vector<LegSpec> legs;  ///< one per leg (filled with defaults)
  std::vector<DoorSpec> doors;
  std::vector<DoorwaySpec> doorways;
  std::vector<PosterSpec> posters;
};

enum class ClutterShape { kCylinder, kBox };

/// A bin, column or pillar standing on the floor.
struct ClutterSpec {
  std::string where;
  std::string kind = "bin";  ///< bin, column, pillar
  ClutterShape shape = ClutterShape::kCylinder;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();    ///< metres
  double radius_m = 0.2;                               ///< cylinder
  Eigen::Vector2d size_m = Eigen::Vector2d(0.4, 0.4);  ///< box, full side lengths
  double yaw_deg = 0.0;                                ///< box
  double z_min_m = 0.0;
  double z_max_m = 1.0;
};

/// Any other rectangle, by its four corners (counter-clockwise seen from the
/// free space, so that (c1 - c0) x (c3 - c0) points into it).
struct FreeRectangleSpec {
  std::string where;
  std::string kind = "wall";
  std::array<Eigen::Vector3d, 4> corners;
};

/// A person walking to and fro along a polyline, as a vertical cylinder:
/// standing at the first waypoint until `start_s`, then walking to the last
/// one and back, again and again, at `speed_m_s` (corners rounded as the
/// robot's path's, radius `corner_radius_m`). Seen by the lasers only.
struct PersonSpec {
  std::string where;
  std::vector<Eigen::Vector2d> waypoints;  ///< metres (>= 2)
  double speed_m_s = 1.2;
  double radius_m = 0.25;  ///< of the cylinder standing for body and legs, metres
  double height_m = 1.75;
  double start_s = 0.0;  ///< seconds after the run's start
  double corner_radius_m = 0.3;
};

/// The robot's path: driven at constant speed with circular corners.
struct PathSpec {
  std::vector<Eigen::Vector2d> waypoints;  ///< metres (>= 2)
  double speed_m_s = 0.4;
  double corner_radius_m = 1.0;      ///< raised to speed / max yaw rate if smaller
  double max_yaw_rate_deg_s = 45.0;  ///< bound on |d yaw / dt|, degrees per second
  double robot_radius_m = 0.25;      ///< clearance kept from every surface, metres
  bool validate(std::string* why) const;
};

/// A voxel world: the occupied voxels of an OctoMap binary tree (.bt) are the
/// building (doc/simulator.md, "Voxel worlds"). The limits bound the memory a
/// damaged or huge file can take before anything is allocated for it.
struct OctomapSpec {
  std::string where;                             ///< JSON path of the block, for messages
  std::string file_as_written;                   ///< the world file's "file" value
  std::filesystem::path file;                    ///< resolved against the world file's directory
  std::uint64_t max_tree_nodes = 20000000;       ///< a tree with more nodes is refused
  std::uint64_t max_occupied_voxels = 20000000;  ///< at the finest resolution (map-eval's limit)
};

struct WorldSpec {
  std::string source_file;  ///< for error messages
  std::string name;
  std::string description;
  std::vector<CorridorSpec> corridors;
  std::vector<ClutterSpec> clutter;
  std::vector<FreeRectangleSpec> rectangles;
  std::vector<PersonSpec> people;      ///< moving, in rectangle and voxel worlds alike
  std::optional<OctomapSpec> octomap;  ///< set: a voxel world (no corridors, clutter, rectangles)
  PathSpec path;
  SensorOptions sensors;
  NoiseOptions noise;
};

/// The kinds a free rectangle may have.
const std::vector<std::string>& freeRectangleKinds();
/// The kinds a clutter object may have.
const std::vector<std::string>& clutterKinds();

}  // namespace pmap::sim
