#include "pmap/sim/voxel_path_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "pmap/common/error.h"
#include "pmap/sim/laser_sim.h"

namespace pmap::sim {
namespace {

constexpr double kStep_m = 0.05;
constexpr double kHeights_m[] = {0.1, 0.4, 1.0};  // as path_check.cpp

std::string format(const char* fmt, double a, double b, double c = 0.0) {
  char text[96];
  std::snprintf(text, sizeof(text), fmt, a, b, c);
  return text;
}

[[noreturn]] void fail(const std::string& file, const std::string& what, const Pose2D& at) {
  throw ConfigError(file + ": path: " + what + format(" near (%.2f, %.2f)", at.x, at.y));
}

std::string voxelName(const VoxelWorld& voxels, const Eigen::Vector3i& v) {
  const Eigen::Vector3d c = voxels.voxelCentre(v);
  return "the occupied voxel (" + std::to_string(v.x()) + ", " + std::to_string(v.y()) + ", " +
         std::to_string(v.z()) + ")" +
         format(" centred at (%.3f, %.3f, %.3f)", c.x(), c.y(), c.z());
}

/// The first occupied voxel of layer `k` whose square comes within `r` of (x, y).
bool touchesLayer(const VoxelWorld& voxels, double x, double y, int k, double r,
                  Eigen::Vector3i& hit) {
  const double res = voxels.resolution_m();
  const int i0 = static_cast<int>(std::floor((x - r) / res));
  const int i1 = static_cast<int>(std::floor((x + r) / res));
  const int j0 = static_cast<int>(std::floor((y - r) / res));
  const int j1 = static_cast<int>(std::floor((y + r) / res));
  for (int i = i0; i <= i1; ++i) {
    for (int j = j0; j <= j1; ++j) {
      const double dx = std::max({i * res - x, 0.0, x - (i + 1) * res});
      const double dy = std::max({j * res - y, 0.0, y - (j + 1) * res});
      if (dx * dx + dy * dy <= r * r && voxels.occupied({i, j, k})) {
        hit = {i, j, k};
        return true;
      }
    }
  }
  return false;
}

}  // namespace

void checkVoxelPathClearance(const VoxelWorld& voxels, const Trajectory& trajectory,
                             double robot_radius_m, const SensorOptions& sensors,
                             const std::string& file) {
  const double res = voxels.resolution_m();
  const double step = std::min(kStep_m, 0.5 * res);
  const int steps = static_cast<int>(std::ceil(trajectory.length_m() / step));
  const double margin = robot_radius_m + res;
  for (int s = 0; s <= steps; ++s) {
    const Pose2D pose = trajectory.poseAtDistance(s * step);
    const Eigen::Vector3d low(pose.x - margin, pose.y - margin, 0.0);
    const Eigen::Vector3d high(pose.x + margin, pose.y + margin, 0.0);
    if (!voxels.inKeyRange(low) || !voxels.inKeyRange(high)) {
      fail(file, "the path leaves the tree's key range", pose);
    }
    for (const double z : kHeights_m) {
      Eigen::Vector3i v;
      const int k = static_cast<int>(std::floor(z / res));
      if (touchesLayer(voxels, pose.x, pose.y, k, robot_radius_m, v)) {
        fail(file,
             format("the robot (radius %.2f m) at %.1f m height touches ", robot_radius_m, z) +
                 voxelName(voxels, v),
             pose);
      }
    }
    for (const LaserOptions* laser : {&sensors.laser_h, &sensors.laser_v}) {
      const Eigen::Vector3d o = laserToWorld(pose, *laser).translation;
      if (voxels.inKeyRange(o) && voxels.occupied(voxels.voxelOf(o))) {
        fail(file, laser->label + " lies inside " + voxelName(voxels, voxels.voxelOf(o)), pose);
      }
    }
  }
}

}  // namespace pmap::sim
