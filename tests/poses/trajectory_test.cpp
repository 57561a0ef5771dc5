#include "pmap/poses/trajectory.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pmap::poses {
namespace {
using mrpt::math::TPose3D;

TEST(Trajectory, InterpolatesPositionLinearlyAndYawAlongTheShortArc) {
  Trajectory t;
  ASSERT_TRUE(t.append(10.0, TPose3D(0, 0, 0, 3.0, 0, 0)));
  ASSERT_TRUE(t.append(11.0, TPose3D(2, 4, 0, -3.0, 0, 0)));
  const auto mid = t.at(10.5, 2.0);
  ASSERT_TRUE(mid);
  EXPECT_NEAR(mid->x, 1.0, 1e-12);
  EXPECT_NEAR(mid->y, 2.0, 1e-12);
  // 3.0 -> -3.0 rad crosses +-pi: the midpoint is pi, not 0.
  EXPECT_NEAR(std::abs(mid->yaw), M_PI, 1e-9);
}

TEST(Trajectory, ExactAtSamplesEmptyOutsideAndInLongGaps) {
  Trajectory t;
  t.append(1.0, TPose3D(1, 0, 0, 0, 0, 0));
  t.append(2.0, TPose3D(2, 0, 0, 0, 0, 0));
  t.append(5.0, TPose3D(5, 0, 0, 0, 0, 0));
  EXPECT_DOUBLE_EQ(t.at(2.0, 0.5)->x, 2.0);
  EXPECT_FALSE(t.at(0.5, 10));
  EXPECT_FALSE(t.at(5.5, 10));
  EXPECT_FALSE(t.at(3.0, 1.0));  // gap of 3 s > 1 s
  EXPECT_NEAR(t.at(3.0, 5.0)->x, 3.0, 1e-12);
}

TEST(Trajectory, SameTimeReplacesOlderIsRefused) {
  Trajectory t;
  t.append(1.0, TPose3D(1, 0, 0, 0, 0, 0));
  EXPECT_TRUE(t.append(1.0, TPose3D(7, 0, 0, 0, 0, 0)));
  EXPECT_EQ(t.size(), 1u);
  EXPECT_DOUBLE_EQ(t.poses()[0].pose.x, 7.0);
  EXPECT_FALSE(t.append(0.5, TPose3D()));
  EXPECT_EQ(t.size(), 1u);
}

TEST(Trajectory, InterpolationOfPitchAndRollIsSpherical) {
  const TPose3D a(0, 0, 0, 0, 0, 0);
  const TPose3D b(0, 0, 0, 0, 0.4, 0);
  const TPose3D m = interpolatePose(a, b, 0.25);
  EXPECT_NEAR(m.pitch, 0.1, 1e-12);
  EXPECT_NEAR(m.yaw, 0.0, 1e-12);
  EXPECT_NEAR(m.roll, 0.0, 1e-12);
}

}  // namespace
}  // namespace pmap::poses
