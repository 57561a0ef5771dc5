// Issue 13, item 12: physically implausible motion is dropped and counted.
#include "pmap/poses/motion_gate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace pmap::poses {
namespace {

using mrpt::math::TPose3D;

TPose3D at(double x, double y = 0.0, double yaw = 0.0) {
  return TPose3D(x, y, 0.0, yaw, 0.0, 0.0);
}

TEST(MotionGate, Item12_OneFlippedOdometryReadingIsDropped) {
  MotionGate gate{MotionLimits{}};
  for (int k = 0; k < 10; ++k) {
    const double t = 0.1 * k;
    const TPose3D reading = k == 5 ? at(2.6e10) : at(0.04 * k);  // 0.4 m/s, one bit flipped
    const auto used = gate.absolute(t, reading);
    if (k == 5) {
      EXPECT_FALSE(used);
    } else {
      ASSERT_TRUE(used);
      EXPECT_DOUBLE_EQ(used->x, 0.04 * k);  // the others pass unchanged
    }
  }
  EXPECT_EQ(gate.stats().dropped(), 1u);
  EXPECT_EQ(gate.stats().too_far, 1u);
  EXPECT_EQ(gate.stats().resets, 0u);
  EXPECT_NE(gate.summary("odometry readings").find("1 odometry readings dropped"),
            std::string::npos);
}

TEST(MotionGate, Item12_AStepBeyondTheSpeedLimitIsDropped) {
  MotionGate gate{MotionLimits{}};
  ASSERT_TRUE(gate.absolute(0.0, at(0.0)));
  EXPECT_FALSE(gate.absolute(0.1, at(1e4)));             // 100 km/s, within max_coordinate_m
  EXPECT_TRUE(gate.absolute(0.2, at(0.08)));             // judged against the last accepted
  EXPECT_FALSE(gate.absolute(0.3, at(0.08, 0.0, 3.0)));  // 172 deg in 0.1 s
  EXPECT_EQ(gate.stats().too_fast, 2u);
}

TEST(MotionGate, Item12_ZeroOrNegativeTimeStepsAreBoundByMaxStep) {
  MotionLimits limits;
  limits.max_step_m = 0.5;
  MotionGate gate{limits};
  ASSERT_TRUE(gate.absolute(1.0, at(0.0)));
  EXPECT_TRUE(gate.absolute(1.0, at(0.4)));   // same time: within max_step_m
  EXPECT_FALSE(gate.absolute(0.5, at(2.0)));  // earlier time: beyond it
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(gate.absolute(nan, at(1.5)));  // unknown time: beyond it
}

TEST(MotionGate, Item12_NonFiniteReadingsAreDropped) {
  MotionGate gate{MotionLimits{}};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(gate.absolute(0.0, at(nan)));
  EXPECT_FALSE(gate.increment(0.1, at(0.0, std::numeric_limits<double>::infinity())));
  EXPECT_EQ(gate.stats().non_finite, 2u);
}

TEST(MotionGate, Item12_AnOdometryResetIsReAnchored) {
  MotionLimits limits;
  limits.reset_after = 3;
  MotionGate gate{limits};
  for (int k = 0; k <= 5; ++k) {
    ASSERT_TRUE(gate.absolute(0.1 * k, at(0.04 * k)));
  }
  // The odometry counter jumps to 500 m and goes on from there.
  EXPECT_FALSE(gate.absolute(0.6, at(500.0)));
  EXPECT_FALSE(gate.absolute(0.7, at(500.04)));
  const auto used = gate.absolute(0.8, at(500.08));  // the third agreeing reading
  ASSERT_TRUE(used);
  // Re-anchored: the jump's first reading sits where the robot was (0.2 m).
  EXPECT_NEAR(used->x, 0.2 + 0.08, 1e-9);
  const auto next = gate.absolute(0.9, at(500.12));
  ASSERT_TRUE(next);
  EXPECT_NEAR(next->x, 0.2 + 0.12, 1e-9);
  EXPECT_EQ(gate.stats().resets, 1u);
  EXPECT_EQ(gate.stats().too_fast, 2u);
}

TEST(MotionGate, Item12_NoResetWhenDisabled) {
  MotionLimits limits;
  limits.reset_after = 0;
  MotionGate gate{limits};
  ASSERT_TRUE(gate.absolute(0.0, at(0.0)));
  for (int k = 1; k <= 20; ++k) {
    EXPECT_FALSE(gate.absolute(0.1 * k, at(1e5 + 0.04 * k)));
  }
  EXPECT_EQ(gate.stats().resets, 0u);
}

TEST(MotionGate, Item12_IncrementsAreJudgedAlone) {
  MotionGate gate{MotionLimits{}};
  EXPECT_TRUE(gate.increment(0.2, at(0.1, 0.0, 0.1)));
  EXPECT_TRUE(gate.increment(std::nan(""), at(0.5)));  // zero timestamps: max_step_m
  EXPECT_FALSE(gate.increment(0.2, at(2.6e10)));
  EXPECT_FALSE(gate.increment(0.2, at(50.0)));
  EXPECT_EQ(gate.stats().dropped(), 2u);
}

TEST(MotionGate, Item12_LimitsValidate) {
  std::string why;
  EXPECT_TRUE(MotionLimits{}.validate(&why));
  MotionLimits bad;
  bad.max_speed_mps = -1;
  EXPECT_FALSE(bad.validate(&why));
  EXPECT_NE(why.find("max_speed_mps"), std::string::npos);
  bad = MotionLimits{};
  bad.max_coordinate_m = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(bad.validate(&why));
}

}  // namespace
}  // namespace pmap::poses
