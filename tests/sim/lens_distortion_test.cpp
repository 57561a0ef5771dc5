#include "pmap/sim/lens_distortion.h"

#include <gtest/gtest.h>

#include <mrpt/img/TCamera.h>
#include <mrpt/math/TPoint3D.h>
#include <mrpt/vision/pinhole.h>
#include <opencv2/imgproc.hpp>

#include "pmap/common/error.h"
#include "pmap/sim/observation_factory.h"
#include "pmap/sim/renderer.h"

namespace pmap::sim {
namespace {

const DistortionCoefficients kBarrel = {-0.22, 0.06, 0.001, -0.0015, -0.004};

TEST(LensDistortion, ZeroCoefficientsAreTheIdentity) {
  const Eigen::Vector2d p(0.7, -0.4);
  EXPECT_EQ(distortNormalised(DistortionCoefficients{}, p), p);
  const auto back = undistortNormalised(DistortionCoefficients{}, p);
  ASSERT_TRUE(back);
  EXPECT_EQ(*back, p);
}

TEST(LensDistortion, UndistortInvertsDistort) {
  for (double x = -1.2; x <= 1.2; x += 0.2) {
    for (double y = -0.9; y <= 0.9; y += 0.15) {
      const Eigen::Vector2d p(x, y);
      const auto back = undistortNormalised(kBarrel, distortNormalised(kBarrel, p));
      ASSERT_TRUE(back) << x << " " << y;
      EXPECT_NEAR((*back - p).norm(), 0.0, 1e-10) << x << " " << y;
    }
  }
}

/// Our forward model is MRPT's: the written cameraParams project like we do.
TEST(LensDistortion, AgreesWithMrptProjection) {
  PinholeIntrinsics k = PinholeIntrinsics::fromFov(640, 480, M_PI / 2);
  k.distortion = kBarrel;
  const auto obs = makeImageObservation("CAM", k, Pose6D{}, "x.jpg", simTimestamp(0.0, 0.0));
  EXPECT_EQ(obs->cameraParams.distortion, mrpt::img::DistortionModel::plumb_bob);
  EXPECT_EQ(obs->cameraParams.k1(), kBarrel[0]);
  EXPECT_EQ(obs->cameraParams.p2(), kBarrel[3]);
  EXPECT_EQ(obs->cameraParams.k3(), kBarrel[4]);
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(0.3, -0.2, 1.0), Eigen::Vector3d(-0.9, 0.6, 1.1),
                                   Eigen::Vector3d(0.05, 0.7, 0.8)}) {
    mrpt::img::TPixelCoordf px;
    mrpt::vision::pinhole::projectPoint_with_distortion(mrpt::math::TPoint3D(p.x(), p.y(), p.z()),
                                                        obs->cameraParams, px);
    const Eigen::Vector2d d = distortNormalised(kBarrel, Eigen::Vector2d(p.x(), p.y()) / p.z());
    EXPECT_NEAR(px.x, k.cx + k.fx * d.x(), 1e-3);
    EXPECT_NEAR(px.y, k.cy + k.fy * d.y(), 1e-3);
  }
}

TEST(LensDistortion, UsabilityRejectsFoldOverAndHugeFields) {
  const PinholeIntrinsics k = PinholeIntrinsics::fromFov(640, 480, M_PI / 2);
  std::string why;
  EXPECT_TRUE(distortionIsUsable(k, kBarrel, &why)) << why;
  EXPECT_TRUE(distortionIsUsable(k, {0.1, 0.0, 0.0, 0.0, 0.0}, &why)) << why;  // pincushion
  EXPECT_FALSE(distortionIsUsable(k, {-0.4, 0.0, 0.0, 0.0, 0.0}, &why));
  EXPECT_NE(why.find("lens.distortion"), std::string::npos) << why;
  PinholeIntrinsics bad = k;
  bad.distortion = {-0.4, 0.0, 0.0, 0.0, 0.0};
  EXPECT_THROW(LensWarp{bad}, ConfigError);
}

TEST(LensDistortion, WarpWithoutDistortionIsTheIdentity) {
  const PinholeIntrinsics k = PinholeIntrinsics::fromFov(64, 48, M_PI / 2);
  const LensWarp warp(k);
  EXPECT_EQ(warp.renderIntrinsics().width_px, 64);
  EXPECT_EQ(warp.renderIntrinsics().cx, k.cx);
  const cv::Mat img(48, 64, CV_32FC3, cv::Scalar(1, 2, 3));
  EXPECT_EQ(warp.apply(img).data, img.data);
}

/// A small white square on a dark (wooden) wall, rendered through a distorted lens,
/// appears where MRPT projects its centre with the observation's cameraParams.
TEST(LensDistortion, RenderedMarkerLandsWhereMrptProjectsIt) {
  World w;
  Surface wall;
  wall.id = 0;
  wall.kind = "door";  // dark wood: only the marker passes the threshold
  wall.rect = Rectangle3::facing(Eigen::Vector3d(-5, -5, 2), Eigen::Vector3d(5, -5, 2),
                                 Eigen::Vector3d(-5, 5, 2), Eigen::Vector3d::Zero());
  wall.poster_indices = {0};
  w.surfaces.push_back(wall);
  const Eigen::Vector3d marker(1.1, 0.75, 2.0);  // towards the image corner
  Poster p;
  p.id = 1;
  p.wall_index = 0;
  p.pixels_per_m = 100;
  p.width_px = p.height_px = 6;
  p.rect = Rectangle3::facing(marker + Eigen::Vector3d(-0.03, -0.03, 0),
                              marker + Eigen::Vector3d(0.03, -0.03, 0),
                              marker + Eigen::Vector3d(-0.03, 0.03, 0), Eigen::Vector3d::Zero());
  w.posters.push_back(p);
  const std::vector<cv::Mat> posters = {cv::Mat(6, 6, CV_8UC3, cv::Scalar::all(255))};
  PinholeIntrinsics k = PinholeIntrinsics::fromFov(320, 240, M_PI / 2);
  k.distortion = kBarrel;
  const LensWarp warp(k);
  EXPECT_GT(warp.renderIntrinsics().width_px, k.width_px);  // barrel: wider ideal field
  const Renderer renderer(w, posters, 1);
  // Camera at the origin looking along +z (the identity optical frame).
  const cv::Mat img = warp.apply(renderer.render(warp.renderIntrinsics(), RigidTransform{}));
  ASSERT_EQ(img.cols, 320);
  cv::Mat grey, bright;
  cv::cvtColor(img, grey, cv::COLOR_BGR2GRAY);
  cv::threshold(grey, bright, 200.0, 1.0, cv::THRESH_BINARY);
  const cv::Moments m = cv::moments(bright, true);
  ASSERT_GT(m.m00, 4.0);
  const auto obs = makeImageObservation("CAM", k, Pose6D{}, "x.jpg", simTimestamp(0.0, 0.0));
  mrpt::img::TPixelCoordf px;
  mrpt::vision::pinhole::projectPoint_with_distortion(
      mrpt::math::TPoint3D(marker.x(), marker.y(), marker.z()), obs->cameraParams, px);
  EXPECT_NEAR(m.m10 / m.m00, px.x, 0.5);
  EXPECT_NEAR(m.m01 / m.m00, px.y, 0.5);
  // Without distortion it would be elsewhere: the test can tell.
  EXPECT_GT(std::abs(k.cx + k.fx * marker.x() / marker.z() - px.x), 3.0);
}

}  // namespace
}  // namespace pmap::sim
