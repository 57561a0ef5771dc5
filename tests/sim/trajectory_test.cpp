#include "pmap/sim/trajectory.h"

#include <gtest/gtest.h>

#include "pmap/common/error.h"

namespace pmap::sim {
namespace {

PathSpec lPath() {
  PathSpec p;
  p.waypoints = {Eigen::Vector2d(0, 0), Eigen::Vector2d(10, 0), Eigen::Vector2d(10, 5)};
  p.corner_radius_m = 1.0;
  return p;
}

TEST(Trajectory, LengthAndEndpoints) {
  const Trajectory t(lPath(), "w.json");
  EXPECT_NEAR(t.length_m(), 15.0 - 2.0 + M_PI / 2.0, 1e-12);
  EXPECT_NEAR(t.duration_s(), t.length_m() / 0.4, 1e-12);
  const Pose2D start = t.poseAtTime(0.0);
  EXPECT_NEAR(start.x, 0.0, 1e-12);
  EXPECT_NEAR(start.yaw, 0.0, 1e-12);
  const Pose2D end = t.poseAtDistance(t.length_m());
  EXPECT_NEAR(end.x, 10.0, 1e-12);
  EXPECT_NEAR(end.y, 5.0, 1e-12);
  EXPECT_NEAR(end.yaw, M_PI / 2.0, 1e-12);
}

TEST(Trajectory, ConstantSpeedContinuousPoseAndBoundedYawRate) {
  const Trajectory t(lPath(), "w.json");
  const double dt = 0.01;
  Pose2D prev = t.poseAtTime(0.0);
  const double max_rate = 0.4 / t.cornerRadius_m();
  for (double time = dt; time <= t.duration_s(); time += dt) {
    const Pose2D p = t.poseAtTime(time);
    const double step = std::hypot(p.x - prev.x, p.y - prev.y);
    EXPECT_NEAR(step, 0.4 * dt, 1e-6);
    EXPECT_LE(std::abs(wrapAngle(p.yaw - prev.yaw)) / dt, max_rate + 1e-9);
    // Heading follows the direction of motion.
    EXPECT_NEAR(wrapAngle(std::atan2(p.y - prev.y, p.x - prev.x) - 0.5 * (p.yaw + prev.yaw)), 0.0,
                1e-3);
    prev = p;
  }
}

TEST(Trajectory, RadiusRaisedToRespectTheYawRate) {
  PathSpec p = lPath();
  p.corner_radius_m = 0.1;
  p.max_yaw_rate_deg_s = 20.0;
  const Trajectory t(p, "w.json");
  EXPECT_NEAR(t.cornerRadius_m(), 0.4 / (20.0 * M_PI / 180.0), 1e-12);
}

TEST(Trajectory, ImpossiblePathsAreConfigErrors) {
  PathSpec u = lPath();
  u.waypoints = {Eigen::Vector2d(0, 0), Eigen::Vector2d(10, 0), Eigen::Vector2d(0, 0)};
  EXPECT_THROW(Trajectory(u, "w.json"), ConfigError);
  PathSpec short_leg = lPath();
  short_leg.waypoints = {Eigen::Vector2d(0, 0), Eigen::Vector2d(10, 0), Eigen::Vector2d(10, 0.5),
                         Eigen::Vector2d(20, 0.5)};
  EXPECT_THROW(Trajectory(short_leg, "w.json"), ConfigError);
  PathSpec same = lPath();
  same.waypoints = {Eigen::Vector2d(0, 0), Eigen::Vector2d(0, 0)};
  EXPECT_THROW(Trajectory(same, "w.json"), ConfigError);
}

}  // namespace
}  // namespace pmap::sim
