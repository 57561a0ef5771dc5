#include "pmap/sim/camera_model.h"

#include <gtest/gtest.h>

#include <mrpt/poses/CPose3D.h>

namespace pmap::sim {
namespace {

const PinholeIntrinsics kK = PinholeIntrinsics::fromFov(640, 480, M_PI / 2);

mrpt::poses::CPose3D toMrpt(const Pose6D& p) {
  return mrpt::poses::CPose3D(p.x, p.y, p.z, p.yaw, p.pitch, p.roll);
}

RigidTransform cameraInWorld(const Pose2D& robot, const CameraMount& mount) {
  return compose(toTransform(robot), toTransform(cameraMountPose(mount)));
}

TEST(CameraModel, Intrinsics) {
  EXPECT_NEAR(kK.fx, 320.0, 1e-9);
  EXPECT_NEAR(kK.cx, 319.5, 1e-12);
  EXPECT_NEAR(kK.cy, 239.5, 1e-12);
}

TEST(CameraModel, ForwardMountIsMrptsLookingAlongX) {
  const Pose6D p = cameraMountPose(CameraMount{"C", {0, 0, 1}, "forward"});
  EXPECT_NEAR(p.yaw, -M_PI / 2, 1e-12);
  EXPECT_NEAR(p.pitch, 0.0, 1e-12);
  EXPECT_NEAR(p.roll, -M_PI / 2, 1e-12);
  const Eigen::Matrix3d r = toTransform(p).rotation;
  EXPECT_TRUE(r.col(2).isApprox(Eigen::Vector3d::UnitX()));   // optical axis = robot +x
  EXPECT_TRUE(r.col(0).isApprox(-Eigen::Vector3d::UnitY()));  // image right = robot right
  EXPECT_TRUE(r.col(1).isApprox(-Eigen::Vector3d::UnitZ()));  // image down = world down
}

TEST(CameraModel, LeftAndRightCamerasSeeTheirSide) {
  const Pose2D robot{2.0, 1.0, 0.6};
  const Eigen::Vector2d fwd(std::cos(robot.yaw), std::sin(robot.yaw));
  const Eigen::Vector2d left(-fwd.y(), fwd.x());
  const CameraMount lm{"CAMERA_LEFT", {0.0, 0.05, 1.0}, "left"};
  const CameraMount rm{"CAMERA_RIGHT", {0.0, -0.05, 1.0}, "right"};
  const RigidTransform lc = cameraInWorld(robot, lm);
  const RigidTransform rc = cameraInWorld(robot, rm);
  auto at = [&](double ahead, double side, double z) {
    const Eigen::Vector2d p = Eigen::Vector2d(robot.x, robot.y) + ahead * fwd + side * left;
    return Eigen::Vector3d(p.x(), p.y(), z);
  };
  // A point 2 m to the left at camera height: centre of the left image.
  const auto centre = projectPoint(kK, lc, at(0.0, 2.05, 1.0));
  ASSERT_TRUE(centre);
  EXPECT_NEAR(centre->x(), kK.cx, 1e-9);
  EXPECT_NEAR(centre->y(), kK.cy, 1e-9);
  EXPECT_FALSE(projectPoint(kK, lc, at(0.0, -2.0, 1.0)));  // behind the left camera
  // Ahead-left is on the right of the left image; higher is up (smaller v).
  const auto ahead = projectPoint(kK, lc, at(1.0, 2.05, 1.5));
  ASSERT_TRUE(ahead);
  EXPECT_GT(ahead->x(), kK.cx + 100);
  EXPECT_NEAR(ahead->y(), kK.cy - kK.fy * 0.5 / 2.0, 1e-9);
  // The right camera: 2 m to the right at the centre, ahead-right on the left.
  const auto rcentre = projectPoint(kK, rc, at(0.0, -2.05, 1.0));
  ASSERT_TRUE(rcentre);
  EXPECT_NEAR(rcentre->x(), kK.cx, 1e-9);
  const auto rahead = projectPoint(kK, rc, at(1.0, -2.05, 1.0));
  ASSERT_TRUE(rahead);
  EXPECT_LT(rahead->x(), kK.cx - 100);
}

TEST(CameraModel, ProjectionMatchesMrpt) {
  const Pose2D robot{-3.0, 7.0, -1.1};
  for (const char* look : {"left", "right", "forward", "backward"}) {
    const CameraMount m{"C", {0.1, 0.05, 1.0}, look};
    const mrpt::poses::CPose3D cam =
        mrpt::poses::CPose3D(robot.x, robot.y, 0, robot.yaw, 0, 0) + toMrpt(cameraMountPose(m));
    const RigidTransform ours = cameraInWorld(robot, m);
    for (const Eigen::Vector3d& p : {Eigen::Vector3d(-1, 5, 1.2), Eigen::Vector3d(-5, 9, 0.3),
                                     Eigen::Vector3d(0, 8, 2.0), Eigen::Vector3d(-4, 6, 1.0)}) {
      double lx, ly, lz;
      cam.inverseComposePoint(p.x(), p.y(), p.z(), lx, ly, lz);
      const auto uv = projectPoint(kK, ours, p);
      ASSERT_EQ(uv.has_value(), lz > 1e-3) << look;
      if (uv) {
        EXPECT_NEAR(uv->x(), kK.cx + kK.fx * lx / lz, 1e-9) << look;
        EXPECT_NEAR(uv->y(), kK.cy + kK.fy * ly / lz, 1e-9) << look;
      }
    }
  }
}

TEST(CameraModel, PixelRayInvertsProjection) {
  const RigidTransform identity;
  const Eigen::Vector3d ray = pixelRay(kK, 100.0, 400.0);
  const auto uv = projectPoint(kK, identity, 3.0 * ray);
  ASSERT_TRUE(uv);
  EXPECT_NEAR(uv->x(), 100.0, 1e-9);
  EXPECT_NEAR(uv->y(), 400.0, 1e-9);
}

}  // namespace
}  // namespace pmap::sim
