#include "pmap/sim/pose.h"

#include <gtest/gtest.h>

#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

namespace pmap::sim {
namespace {

TEST(Pose, RotationMatchesMrptCPose3D) {
  const double cases[][3] = {
      {0.3, -0.4, 0.2}, {0.0, -M_PI / 2, 0.0}, {M_PI, 0.0, -M_PI / 2}, {-2.0, 1.0, 3.0}};
  for (const auto& c : cases) {
    const mrpt::poses::CPose3D mrpt_pose(1.0, 2.0, 3.0, c[0], c[1], c[2]);
    const Eigen::Matrix3d ours = rotationYawPitchRoll(c[0], c[1], c[2]);
    const Eigen::Matrix3d theirs = mrpt_pose.getRotationMatrix().asEigen();
    EXPECT_TRUE(ours.isApprox(theirs, 1e-12)) << ours << "\nvs MRPT\n" << theirs;
  }
}

TEST(Pose, PositivePitchIsNoseDown) {
  const Eigen::Vector3d x = rotationYawPitchRoll(0.0, 0.3, 0.0) * Eigen::Vector3d::UnitX();
  EXPECT_LT(x.z(), 0.0);
}

TEST(Pose, ComposeMatchesMrpt) {
  const Pose6D a{1.0, -2.0, 0.5, 0.4, -0.1, 0.2};
  const Pose6D b{0.3, 0.2, -0.1, -1.0, 0.5, 0.1};
  const RigidTransform ab = compose(toTransform(a), toTransform(b));
  const mrpt::poses::CPose3D ma(a.x, a.y, a.z, a.yaw, a.pitch, a.roll);
  const mrpt::poses::CPose3D mb(b.x, b.y, b.z, b.yaw, b.pitch, b.roll);
  const mrpt::poses::CPose3D mab = ma + mb;
  EXPECT_TRUE(ab.rotation.isApprox(mab.getRotationMatrix().asEigen(), 1e-12));
  EXPECT_NEAR(ab.translation.x(), mab.x(), 1e-12);
  EXPECT_NEAR(ab.translation.y(), mab.y(), 1e-12);
  EXPECT_NEAR(ab.translation.z(), mab.z(), 1e-12);
}

TEST(Pose, Planar2DComposeAndBetweenAreInverse) {
  const Pose2D a{1.0, 2.0, 2.5};
  const Pose2D b{-0.5, 0.3, 1.2};
  const Pose2D c = compose(a, b);
  const mrpt::poses::CPose2D mc =
      mrpt::poses::CPose2D(a.x, a.y, a.yaw) + mrpt::poses::CPose2D(b.x, b.y, b.yaw);
  EXPECT_NEAR(c.x, mc.x(), 1e-12);
  EXPECT_NEAR(c.y, mc.y(), 1e-12);
  EXPECT_NEAR(c.yaw, mc.phi(), 1e-12);
  const Pose2D back = between(a, c);
  EXPECT_NEAR(back.x, b.x, 1e-12);
  EXPECT_NEAR(back.y, b.y, 1e-12);
  EXPECT_NEAR(back.yaw, b.yaw, 1e-12);
}

TEST(Pose, WrapAngle) {
  EXPECT_NEAR(wrapAngle(3.0 * M_PI), M_PI, 1e-12);
  EXPECT_NEAR(wrapAngle(-M_PI), M_PI, 1e-12);
  EXPECT_NEAR(wrapAngle(0.5), 0.5, 1e-15);
  EXPECT_NEAR(wrapAngle(-7.0), -7.0 + 2.0 * M_PI, 1e-12);
}

}  // namespace
}  // namespace pmap::sim
