#include "pmap/sim/odometry_sim.h"

#include <gtest/gtest.h>

namespace pmap::sim {
namespace {

/// Drives 10 m straight in 0.08 m steps; returns the odometry pose.
Pose2D driveTenMetres(const NoiseOptions& noise, std::uint64_t seed) {
  OdometrySimulator odo(noise, seed);
  for (int i = 0; i < 125; ++i) {
    odo.advance(Pose2D{0.08, 0.0, 0.0});
  }
  return odo.pose();
}

TEST(OdometrySim, SystematicScaleAndHeadingDrift) {
  NoiseOptions noise;
  noise.odometry_random_signs = false;
  noise.odometry_sigma_xy_m = 0.0;
  noise.odometry_sigma_yaw_deg = 0.0;
  OdometrySimulator odo(noise, 1);
  EXPECT_DOUBLE_EQ(odo.scaleError(), 0.02);
  EXPECT_DOUBLE_EQ(odo.headingDriftRadPerM(), M_PI / 180.0);
  const Pose2D p = driveTenMetres(noise, 1);
  // Heading drifts by 1 deg per metre travelled: 10 deg after 10 m.
  EXPECT_NEAR(p.yaw, 10.0 * M_PI / 180.0, 1e-9);
  // Distance along the (curving) odometry path is 2 % longer.
  const double chord = std::hypot(p.x, p.y);
  EXPECT_GT(chord, 10.1);
  EXPECT_LT(chord, 10.2 + 1e-9);
}

TEST(OdometrySim, SignsComeFromTheSeed) {
  NoiseOptions noise;
  bool seen_neg_scale = false;
  bool seen_pos_scale = false;
  bool seen_neg_drift = false;
  bool seen_pos_drift = false;
  for (std::uint64_t seed = 0; seed < 16; ++seed) {
    const OdometrySimulator odo(noise, seed);
    EXPECT_DOUBLE_EQ(std::abs(odo.scaleError()), 0.02);
    EXPECT_DOUBLE_EQ(std::abs(odo.headingDriftRadPerM()), M_PI / 180.0);
    (odo.scaleError() < 0 ? seen_neg_scale : seen_pos_scale) = true;
    (odo.headingDriftRadPerM() < 0 ? seen_neg_drift : seen_pos_drift) = true;
    const OdometrySimulator again(noise, seed);
    EXPECT_EQ(odo.scaleError(), again.scaleError());
  }
  EXPECT_TRUE(seen_neg_scale && seen_pos_scale && seen_neg_drift && seen_pos_drift);
}

TEST(OdometrySim, WhiteNoiseIsSmallAndDeterministic) {
  NoiseOptions noise;
  const Pose2D a = driveTenMetres(noise, 9);
  const Pose2D b = driveTenMetres(noise, 9);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.yaw, b.yaw);
  EXPECT_NEAR(std::abs(a.yaw), 10.0 * M_PI / 180.0, 0.02);
}

TEST(OdometrySim, ReturnsTheMeasuredIncrement) {
  NoiseOptions noise;
  noise.odometry_random_signs = false;
  noise.odometry_sigma_xy_m = 0.0;
  noise.odometry_sigma_yaw_deg = 0.0;
  OdometrySimulator odo(noise, 1);
  const Pose2D inc = odo.advance(Pose2D{1.0, 0.0, 0.1});
  EXPECT_DOUBLE_EQ(inc.x, 1.02);
  EXPECT_NEAR(inc.yaw, 0.1 + M_PI / 180.0, 1e-12);
  EXPECT_DOUBLE_EQ(odo.pose().x, 1.02);
}

}  // namespace
}  // namespace pmap::sim
