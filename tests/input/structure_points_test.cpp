#include "pmap/input/structure_points.h"

#include <gtest/gtest.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationPointCloud.h>

#include <cmath>
#include <limits>

namespace pmap::input {
namespace {

mrpt::obs::CObservation2DRangeScan verticalScan(float range) {
  mrpt::obs::CObservation2DRangeScan s;
  s.aperture = M_PI;
  s.rightToLeft = true;
  s.maxRange = 30;
  s.sensorPose = mrpt::poses::CPose3D(0, 0, 0.3, 0, -M_PI / 2, 0);
  s.resizeScan(181);
  for (int i = 0; i < 181; ++i) {
    s.setScanRange(i, range);
    s.setScanRangeValidity(i, true);
  }
  return s;
}

TEST(StructurePoints, VerticalScanBeamsGoRightUpLeft) {
  const StructureScan out = extractStructureScan(verticalScan(2.0f), 7);
  ASSERT_EQ(out.points.size(), 181u);
  EXPECT_EQ(out.index, 7);
  EXPECT_EQ(out.cols, 181);
  // Beam 0: right (robot -y); beam 90: straight up; beam 180: left.
  EXPECT_NEAR(out.points[0].y(), -2.0, 1e-6);
  EXPECT_NEAR(out.points[0].z(), 0.3, 1e-6);
  EXPECT_NEAR(out.points[90].z(), 2.3, 1e-6);
  EXPECT_NEAR(out.points[90].x(), 0.0, 1e-6);
  EXPECT_NEAR(out.points[180].y(), 2.0, 1e-6);
}

TEST(StructurePoints, NonFiniteInvalidAndOutOfRangeAreDroppedAndCounted) {
  auto s = verticalScan(2.0f);
  s.setScanRange(3, std::numeric_limits<float>::quiet_NaN());
  s.setScanRange(4, std::numeric_limits<float>::infinity());
  s.setScanRangeValidity(5, false);
  s.setScanRange(6, 0.0f);
  s.setScanRange(7, -1.0f);
  s.setScanRange(8, 31.0f);
  const StructureScan out = extractStructureScan(s, 0);
  EXPECT_EQ(out.points.size(), 181u - 6u);
  EXPECT_EQ(out.dropped.non_finite, 2u);
  EXPECT_EQ(out.dropped.invalid, 1u);
  EXPECT_EQ(out.dropped.out_of_range, 3u);
  for (const auto& p : out.points) {
    EXPECT_TRUE(p.allFinite());
  }
  EXPECT_EQ(out.beams[3], 9);  // beams keep their own index
}

TEST(StructurePoints, NanSensorPoseDropsTheScan) {
  auto s = verticalScan(2.0f);
  s.sensorPose.x(std::numeric_limits<double>::quiet_NaN());
  const StructureScan out = extractStructureScan(s, 0);
  EXPECT_TRUE(out.points.empty());
  EXPECT_EQ(out.dropped.non_finite, 1u);
}

TEST(StructurePoints, EmptyScanGivesNoPoints) {
  mrpt::obs::CObservation2DRangeScan s;
  const StructureScan out = extractStructureScan(s, 0);
  EXPECT_TRUE(out.points.empty());
  EXPECT_EQ(out.dropped.total(), 0u);
}

TEST(StructurePoints, PointCloudIsTransformedBySensorPose) {
  mrpt::obs::CObservationPointCloud pc;
  auto cloud = std::make_shared<mrpt::maps::CSimplePointsMap>();
  cloud->insertPoint(1, 0, 0);
  cloud->insertPoint(std::numeric_limits<float>::quiet_NaN(), 0, 0);
  pc.pointcloud = cloud;
  pc.sensorPose = mrpt::poses::CPose3D(0, 0, 1, M_PI / 2, 0, 0);
  const StructureScan out = extractStructureScan(pc, 0);
  ASSERT_EQ(out.points.size(), 1u);
  EXPECT_NEAR(out.points[0].x(), 0.0, 1e-9);
  EXPECT_NEAR(out.points[0].y(), 1.0, 1e-9);
  EXPECT_NEAR(out.points[0].z(), 1.0, 1e-9);
  EXPECT_FALSE(out.organised);
  EXPECT_EQ(out.dropped.non_finite, 1u);
}

}  // namespace
}  // namespace pmap::input
