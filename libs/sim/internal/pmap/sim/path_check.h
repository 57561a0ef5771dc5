// Checks that the robot's trajectory never passes through a surface or clutter
// object and keeps its clearance (robot radius) at three heights.
#pragma once

#include <string>

#include "pmap/sim/ray_caster.h"
#include "pmap/sim/trajectory.h"

namespace pmap::sim {

/// Throws ConfigError naming `file`, "path", the object id and kind and the
/// place where the trajectory crosses it or comes closer than `robot_radius_m`.
/// `who` and `moves` name the mover in the message ("the robot" "drives",
/// "the person" "walks").
void checkPathClearance(const RayCaster& caster, const Trajectory& trajectory,
                        double robot_radius_m, const std::string& file,
                        const std::string& who = "the robot", const std::string& moves = "drives");

}  // namespace pmap::sim
