#include "pmap/points/point_map.h"

#include <gtest/gtest.h>

#include <mrpt/poses/CPose3D.h>

#include <cmath>
#include <random>

namespace pmap::points {
namespace {

TEST(PointMap, TransformsByTheRobotPoseAndKeepsIndices) {
  input::StructureScan scan;
  scan.index = 42;
  scan.timestamp = 3.5;
  scan.label = "LASER_V";
  scan.sensor_pose = mrpt::math::TPose3D(0, 0, 0.3, 0, -M_PI / 2, 0);
  scan.points = {{1, 0, 0}, {0, 1, 2}};
  scan.beams = {5, 9};
  PointMap map;
  map.addScan(scan, mrpt::math::TPose3D(10, 20, 0, M_PI / 2, 0, 0));
  ASSERT_EQ(map.size(), 2u);
  EXPECT_NEAR(map.xyz()[0].x(), 10.0, 1e-12);
  EXPECT_NEAR(map.xyz()[0].y(), 21.0, 1e-12);
  EXPECT_NEAR(map.xyz()[1].x(), 9.0, 1e-12);
  EXPECT_NEAR(map.xyz()[1].z(), 2.0, 1e-12);
  EXPECT_EQ(map.scanIndex()[1], 42);
  EXPECT_EQ(map.beamIndex()[1], 9);
  const ScanRecord& r = map.scans()[0];
  EXPECT_NEAR(r.sensor_pose.x, 10.0, 1e-12);
  EXPECT_NEAR(r.sensor_pose.z, 0.3, 1e-12);
  EXPECT_NEAR(r.sensor_pose.pitch, -M_PI / 2, 1e-9);
  EXPECT_EQ(r.num_points, 2u);
}

// Issue 15 item 4: a moved scan lands where adding it at the new pose would
// have put it (points, robot and sensor poses), for random poses; the other
// scans do not move.
TEST(PointMap, Item15_MovingAScanEqualsPlacingItAtTheNewPose) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  auto randomPose = [&] {
    return mrpt::math::TPose3D(u(rng), u(rng), 0.1 * u(rng), u(rng), 0.1 * u(rng), 0.1 * u(rng));
  };
  for (int trial = 0; trial < 20; ++trial) {
    input::StructureScan scan;
    scan.sensor_pose = mrpt::math::TPose3D(0.2, 0, 0.3, 0.1, -M_PI / 2, 0);
    for (int i = 0; i < 5; ++i) {
      scan.points.emplace_back(u(rng), u(rng), u(rng));
      scan.beams.push_back(i);
    }
    const mrpt::math::TPose3D before = randomPose();
    const mrpt::math::TPose3D after = randomPose();
    PointMap moved;
    moved.addScan(scan, randomPose());
    moved.addScan(scan, before);
    const std::vector<Eigen::Vector3d> first(moved.xyz().begin(), moved.xyz().begin() + 5);
    moved.moveScan(1, after);
    PointMap direct;
    direct.addScan(scan, after);
    for (std::size_t i = 0; i < 5; ++i) {
      EXPECT_LT((moved.xyz()[5 + i] - direct.xyz()[i]).norm(), 1e-9);
      EXPECT_EQ(moved.xyz()[i], first[i]);  // scan 0 stays
    }
    const ScanRecord& m = moved.scans()[1];
    const ScanRecord& d = direct.scans()[0];
    EXPECT_LT(mrpt::poses::CPose3D(m.sensor_pose).distanceTo(mrpt::poses::CPose3D(d.sensor_pose)),
              1e-9);
    EXPECT_NEAR(m.robot_pose.yaw, after.yaw, 1e-12);
  }
}

}  // namespace
}  // namespace pmap::points
