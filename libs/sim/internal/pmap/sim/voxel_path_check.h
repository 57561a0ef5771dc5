// The path check of a voxel world (path_check.h does it for rectangles and
// solids): the robot's disc of radius robot_radius_m, at the heights
// path_check.cpp checks (0.1, 0.4 and 1.0 m above the floor z = 0), must not
// overlap an occupied voxel anywhere along the trajectory (sampled every
// 5 cm, and at most half a voxel apart), and no laser may sit inside one.
// Unknown space counts as free, as it does for the lasers.
#pragma once

#include <string>

#include "pmap/sim/sensor_options.h"
#include "pmap/sim/trajectory.h"
#include "pmap/sim/voxel_world.h"

namespace pmap::sim {

/// Throws ConfigError naming `file`, "path", the voxel (its index and centre)
/// and the place where the robot touches it.
void checkVoxelPathClearance(const VoxelWorld& voxels, const Trajectory& trajectory,
                             double robot_radius_m, const SensorOptions& sensors,
                             const std::string& file);

}  // namespace pmap::sim
