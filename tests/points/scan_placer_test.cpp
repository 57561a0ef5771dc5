#include "pmap/points/scan_placer.h"

#include <gtest/gtest.h>

namespace pmap::points {
namespace {
using mrpt::math::TPose3D;

input::StructureScan scanAt(double t) {
  input::StructureScan s;
  s.timestamp = t;
  s.index = static_cast<std::int64_t>(t * 10);
  s.points = {{0, 0, 1}};
  s.beams = {0};
  s.cols = 1;
  return s;
}

TEST(ScanPlacer, WaitsUntilThePoseAroundTheScanIsFinal) {
  PointMap map;
  ScanPlacer placer(map, 1.0, nullptr);
  poses::Trajectory traj;
  traj.append(1.0, TPose3D(1, 0, 0, 0, 0, 0));
  placer.add(scanAt(1.1));
  traj.append(1.2, TPose3D(2, 0, 0, 0, 0, 0));  // may still be replaced
  placer.drain(traj, false);
  EXPECT_EQ(map.size(), 0u);
  traj.append(1.2, TPose3D(1.2, 0, 0, 0, 0, 0));  // the corrected pose
  traj.append(1.4, TPose3D(1.4, 0, 0, 0, 0, 0));
  placer.drain(traj, false);
  ASSERT_EQ(map.size(), 1u);
  EXPECT_NEAR(map.xyz()[0].x(), 1.1, 1e-12);  // between 1.0 and the corrected 1.2
}

TEST(ScanPlacer, CountsScansWithoutPose) {
  PointMap map;
  ScanPlacer placer(map, 0.5, nullptr);
  poses::Trajectory traj;
  traj.append(1.0, TPose3D());
  traj.append(3.0, TPose3D());
  placer.add(scanAt(0.5));  // before the first pose
  placer.add(scanAt(2.0));  // in a 2 s gap
  placer.add(scanAt(3.5));  // after the last pose
  placer.drain(traj, true);
  EXPECT_EQ(placer.stats().placed, 0u);
  EXPECT_EQ(placer.stats().without_pose, 3u);
  EXPECT_EQ(placer.pending(), 0u);
}

TEST(ScanPlacer, CallsBackForEveryPlacedScan) {
  PointMap map;
  int calls = 0;
  ScanPlacer placer(map, 1.0, [&](const input::StructureScan&, std::size_t) { ++calls; });
  placer.add(scanAt(0.0));
  placer.placeAllAt(TPose3D());
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(map.size(), 1u);
}

// Issue 15 item 4: after a loop closure rewrote the past trajectory, placed
// scans move to the new trajectory's pose at their time; unchanged ones and
// ones the trajectory no longer covers stay.
TEST(ScanPlacer, Item15_PlacedScansFollowARewrittenTrajectory) {
  PointMap map;
  ScanPlacer placer(map, 1.0, nullptr);
  poses::Trajectory traj;
  traj.append(1.0, TPose3D(1, 0, 0, 0, 0, 0));
  traj.append(2.0, TPose3D(2, 0, 0, 0, 0, 0));
  traj.append(3.0, TPose3D(3, 0, 0, 0, 0, 0));
  placer.add(scanAt(1.0));
  placer.add(scanAt(2.5));
  placer.drain(traj, true);
  ASSERT_EQ(map.scans().size(), 2u);
  EXPECT_TRUE(placer.follow(traj).empty());  // nothing changed
  poses::Trajectory corrected;  // the loop closure: the second half moved up 1 m and turned
  corrected.append(1.0, TPose3D(1, 0, 0, 0, 0, 0));
  corrected.append(2.0, TPose3D(2, 1, 0, M_PI / 2, 0, 0));
  corrected.append(3.0, TPose3D(2, 2, 0, M_PI / 2, 0, 0));
  const std::vector<std::size_t> moved = placer.follow(corrected);
  ASSERT_EQ(moved, std::vector<std::size_t>{1});
  EXPECT_NEAR(map.scans()[1].robot_pose.y, 1.5, 1e-12);
  EXPECT_NEAR(map.xyz()[1].x(), 2.0, 1e-12);  // (0, 0, 1) at (2, 1.5) facing +y
  EXPECT_NEAR(map.xyz()[1].y(), 1.5, 1e-12);
  EXPECT_NEAR(map.xyz()[0].x(), 1.0, 1e-12);
  poses::Trajectory shorter;  // no longer covers scan 0's time: it stays
  shorter.append(2.0, TPose3D(0, 0, 0, 0, 0, 0));
  shorter.append(3.0, TPose3D(0, 0, 0, 0, 0, 0));
  EXPECT_EQ(placer.follow(shorter), std::vector<std::size_t>{1});
  EXPECT_NEAR(map.xyz()[0].x(), 1.0, 1e-12);
}

}  // namespace
}  // namespace pmap::points
