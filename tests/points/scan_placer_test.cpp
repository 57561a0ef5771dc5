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

}  // namespace
}  // namespace pmap::points
