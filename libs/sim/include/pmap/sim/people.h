// People walking through the building (world files' "people"): each is a
// vertical cylinder moving to and fro along its own path, so that the lasers
// see it at a different place in every scan. Where one is at a time t is a
// pure function of t: the same run gives the same scans.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "pmap/sim/shapes.h"
#include "pmap/sim/trajectory.h"
#include "pmap/sim/world_spec.h"

namespace pmap::sim {

class WalkingPerson {
 public:
  /// Throws ConfigError naming `file` and the spec's JSON path for a path a
  /// person cannot walk (U-turns, coincident waypoints, too short segments).
  WalkingPerson(const PersonSpec& spec, const std::string& file);

  int id = -1;
  const PersonSpec& spec() const { return spec_; }
  /// The cylinder standing for the person `t_s` seconds after the run's start.
  VerticalCylinder at(double t_s) const;
  /// The walk from the first waypoint to the last (walked there and back).
  const Trajectory& walk() const { return walk_; }

 private:
  PersonSpec spec_;
  Trajectory walk_;
};

/// Where the people are at one time: their cylinders, computed once for all
/// the beams of a scan.
class PeopleAt {
 public:
  PeopleAt(const std::vector<WalkingPerson>& people, double t_s);

  /// The nearest person hit by the ray origin + t dir with t in
  /// (t_min, t_max]: the person's id, t and the cylinder's normal there.
  struct Hit {
    int id = -1;
    ShapeHit hit;
  };
  std::optional<Hit> cast(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double t_min,
                          double t_max) const;

 private:
  std::vector<VerticalCylinder> cylinders_;
  std::vector<int> ids_;
};

}  // namespace pmap::sim
