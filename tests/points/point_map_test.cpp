#include "pmap/points/point_map.h"

#include <gtest/gtest.h>

#include <cmath>

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

}  // namespace
}  // namespace pmap::points
