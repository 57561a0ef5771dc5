#include "pmap/sim/voxel_path_check.h"

#include <gtest/gtest.h>

#include "pmap/common/error.h"

namespace pmap::sim {
namespace {

/// A 6 x 4 x 2.5 m box room of 10 cm voxels, plus extra occupied voxels.
VoxelWorld room(const std::vector<Eigen::Vector3i>& extra = {}) {
  std::vector<VoxelWorld::Block> blocks;
  for (int i = -1; i <= 60; ++i) {
    for (int j = -1; j <= 40; ++j) {
      for (int k = -1; k <= 25; ++k) {
        if (i < 0 || i >= 60 || j < 0 || j >= 40 || k < 0 || k >= 25) {
          blocks.push_back({Eigen::Vector3i(i, j, k), 1});
        }
      }
    }
  }
  for (const Eigen::Vector3i& v : extra) {
    blocks.push_back({v, 1});
  }
  return VoxelWorld(0.1, blocks);
}

std::string errorOf(const VoxelWorld& voxels, const std::vector<Eigen::Vector2d>& waypoints,
                    double radius = 0.25) {
  PathSpec spec;
  spec.waypoints = waypoints;
  spec.robot_radius_m = radius;
  const Trajectory trajectory(spec, "w.json");
  try {
    checkVoxelPathClearance(voxels, trajectory, radius, SensorOptions(), "w.json");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(VoxelPathCheck, AClearPathPasses) {
  EXPECT_EQ(errorOf(room(), {{1.0, 2.0}, {5.0, 2.0}}), "");
  EXPECT_EQ(errorOf(room(), {{0.5, 0.3}, {5.5, 0.3}}), "");  // 5 cm from the wall
}

TEST(VoxelPathCheck, APillarOnThePathIsNamed) {
  std::vector<Eigen::Vector3i> pillar;
  for (int k = 0; k < 25; ++k) {
    pillar.emplace_back(30, 20, k);
  }
  const std::string e = errorOf(room(pillar), {{1.0, 2.05}, {5.0, 2.05}});
  EXPECT_NE(e.find("w.json: path: the robot (radius 0.25 m) at 0.1 m height touches the occupied "
                   "voxel (30, 20, 1) centred at (3.050, 2.050, 0.150) near (2."),
            std::string::npos)
      << e;
}

TEST(VoxelPathCheck, TooCloseToAWall) {
  const std::string e = errorOf(room(), {{0.5, 0.2}, {5.5, 0.2}});
  EXPECT_NE(e.find("touches the occupied voxel"), std::string::npos) << e;
  EXPECT_NE(e.find("near (0.50, 0.20)"), std::string::npos) << e;
}

TEST(VoxelPathCheck, ALaserInsideAVoxel) {
  // The pose laser sits 0.2 m ahead of the robot at 0.4 m: in voxel (12, 20, 4)
  // at the start, where the robot itself (radius 0) is clear.
  const std::string e = errorOf(room({{12, 20, 4}}), {{1.05, 2.05}, {5.0, 2.05}}, 0.0);
  EXPECT_NE(e.find("path: LASER_H lies inside the occupied voxel (12, 20, 4)"), std::string::npos)
      << e;
}

}  // namespace
}  // namespace pmap::sim
