// The simulator's ground truth (PREFIX.gt.json, doc/ground-truth.md), as
// map-eval needs it. Read strictly: a missing or mistyped field is an
// InputError naming the file and the field.
#pragma once

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "pmap/poses/trajectory.h"

namespace pmap::eval {

struct GtRectangle {
  int id = -1;
  std::string kind;  ///< wall, door, ceiling, floor, jamb, ...
  std::array<Eigen::Vector3d, 4> corners;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  int parent = -1;
};

struct GtCylinder {
  int id = -1;
  std::string kind;  ///< bin, column, ...
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 0;
  double z_min = 0;
  double z_max = 0;
};

struct GtBox {
  int id = -1;
  std::string kind;
  Eigen::Vector3d min = Eigen::Vector3d::Zero();
  Eigen::Vector3d max = Eigen::Vector3d::Zero();
  double yaw = 0;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  /// p in the box's own frame (centre at the origin, no yaw), where the box
  /// spans [min, max].
  Eigen::Vector3d local(const Eigen::Vector3d& p) const;
};

/// A flush poster (texture only): corners bottom-left, bottom-right,
/// top-right, top-left seen from the corridor; image row 0 is the top edge.
struct GtPoster {
  int id = -1;
  int wall_id = -1;
  std::array<Eigen::Vector3d, 4> corners;
  std::filesystem::path image;  ///< resolved against the gt.json's directory
  double pixels_per_m = 0;
};

struct GroundTruth {
  std::string world;
  double sigma_m = 0;
  poses::Trajectory poses;
  std::vector<GtRectangle> surfaces;
  std::vector<GtCylinder> cylinders;
  std::vector<GtBox> boxes;
  std::vector<GtPoster> posters;
  /// Ids of the people walking through (gt.json "people"): their hits lie on
  /// no fixed object, so they count as clutter and are not distance-checked.
  std::vector<int> people;

  /// hits[scan index][beam] = id hit by the true ray, -1 for nothing.
  std::map<std::int64_t, std::vector<int>> hits;

  const GtRectangle* surface(int id) const;
  bool isClutter(int id) const;
  bool isPerson(int id) const;
  /// Distance from p to the object `id` (rectangle: closest point of the
  /// finite rectangle; cylinder / box: their surface). Negative id: NaN.
  double distance(int id, const Eigen::Vector3d& p) const;
};

/// Reads PREFIX.gt.json. Throws InputError.
GroundTruth readGroundTruth(const std::filesystem::path& path);

/// Distance from p to a cylinder's surface (side and caps; inside too).
double distanceToCylinder(const GtCylinder& c, const Eigen::Vector3d& p);

/// Distance from p to a box's surface (inside too).
double distanceToBox(const GtBox& b, const Eigen::Vector3d& p);

/// Distance from p to the closest point of a planar convex quadrilateral
/// (a rectangle given by its four corners in order).
double distanceToRectangle(const std::array<Eigen::Vector3d, 4>& corners, const Eigen::Vector3d& p);

}  // namespace pmap::eval
