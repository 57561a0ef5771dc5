#include "pmap/texture/camera_frame.h"

#include <gtest/gtest.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/poses/CPose3D.h>

#include "synthetic_views.h"

namespace pmap::texture {
namespace {

TEST(CameraFrame, PointOnTheOpticalAxisProjectsToThePrincipalPoint) {
  const CameraFrame f = test::lookAt({1, 2, 1}, {0, 1, 0}, {0, 0, 1}, "c");
  const auto px = f.project({1, 5, 1});
  ASSERT_TRUE(px);
  EXPECT_NEAR(px->x(), 319.5, 1e-9);
  EXPECT_NEAR(px->y(), 239.5, 1e-9);
  EXPECT_FALSE(f.project({1, 0, 1}));  // behind
}

TEST(CameraFrame, ImageAxesFollowMrptsOpticalFrame) {
  // +X right, +Y down: a point to the right and above lands right and up.
  const CameraFrame f = test::lookAt({0, 0, 1}, {0, 1, 0}, {0, 0, 1}, "c");
  const auto px = f.project({0.5, 2, 1.5});
  ASSERT_TRUE(px);
  EXPECT_NEAR(px->x(), 319.5 + 320 * 0.25, 1e-9);
  EXPECT_NEAR(px->y(), 239.5 - 320 * 0.25, 1e-9);
}

TEST(CameraFrame, MakeFrameMatchesMrptComposition) {
  auto obs = std::make_shared<mrpt::obs::CObservationImage>();
  obs->sensorLabel = "CAMERA_LEFT";
  obs->cameraParams.ncols = 640;
  obs->cameraParams.nrows = 480;
  obs->cameraParams.intrinsicParams(0, 0) = 320;
  obs->cameraParams.intrinsicParams(1, 1) = 300;
  obs->cameraParams.intrinsicParams(0, 2) = 319.5;
  obs->cameraParams.intrinsicParams(1, 2) = 239.5;
  obs->cameraPose = mrpt::poses::CPose3D(0, 0.05, 1.0, 0, 0, mrpt::DEG2RAD(-90));  // looks left
  const mrpt::poses::CPose3D robot(2, 3, 0, mrpt::DEG2RAD(30), 0, 0);
  const CameraFrame f = makeFrame(obs, robot);
  const mrpt::poses::CPose3D cam = robot + obs->cameraPose;
  const mrpt::math::TPoint3D world(1.0, 5.0, 1.3);
  const mrpt::math::TPoint3D local = cam.inverseComposePoint(world);
  ASSERT_GT(local.z, 0);
  const auto px = f.project({world.x, world.y, world.z});
  ASSERT_TRUE(px);
  EXPECT_NEAR(px->x(), 320 * local.x / local.z + 319.5, 1e-9);
  EXPECT_NEAR(px->y(), 300 * local.y / local.z + 239.5, 1e-9);
  EXPECT_NEAR((f.centre - Eigen::Vector3d(cam.x(), cam.y(), cam.z())).norm(), 0, 1e-12);
}

TEST(CameraFrame, RadialDistortionMovesOffAxisPointsOutwards) {
  CameraFrame f = test::lookAt({0, 0, 0}, {0, 1, 0}, {0, 0, 1}, "c");
  const Eigen::Vector3d p(0.5, 2, 0);
  const double undistorted = f.project(p)->x();
  f.dist[0] = 0.1;  // k1 > 0: barrel to pincushion, points move away from the centre
  EXPECT_GT(f.project(p)->x(), undistorted);
  EXPECT_NEAR(f.project({0, 2, 0})->x(), 319.5, 1e-12);  // the centre stays
}

TEST(CameraFrame, ScaledFrameProjectsToScaledPixels) {
  const CameraFrame f = test::lookAt({0, 0, 0}, {0, 1, 0}, {0, 0, 1}, "c");
  const CameraFrame g = f.scaled(0.125);
  EXPECT_EQ(g.width, 80);
  EXPECT_EQ(g.height, 60);
  EXPECT_DOUBLE_EQ(g.scale, 0.125);
  const Eigen::Vector3d p(0.3, 2, -0.2);
  // Pixel centres: x' + 0.5 = (x + 0.5) / 8.
  EXPECT_NEAR(g.project(p)->x() + 0.5, (f.project(p)->x() + 0.5) / 8, 1e-9);
  EXPECT_NEAR(g.project(p)->y() + 0.5, (f.project(p)->y() + 0.5) / 8, 1e-9);
}

TEST(CameraFrame, ExternalImagesDirFollowsMrptsConvention) {
  const auto dir = std::filesystem::temp_directory_path() / "pmap_images_dir_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "run_images");
  EXPECT_EQ(std::filesystem::path(externalImagesDir(dir / "run.rawlog")).lexically_normal(),
            (dir / "run_images").lexically_normal());
  std::filesystem::create_directories(dir / "run_Images");
  EXPECT_EQ(std::filesystem::path(externalImagesDir(dir / "run.rawlog")).lexically_normal(),
            (dir / "run_Images").lexically_normal());
  EXPECT_EQ(std::filesystem::path(externalImagesDir(dir / "other.rawlog")).filename(), "Images");
  std::filesystem::remove_all(dir);
}

TEST(CameraFrame, MissingExternalImageIsAnInputErrorNamingTheFile) {
  auto obs = std::make_shared<mrpt::obs::CObservationImage>();
  obs->sensorLabel = "CAM";
  obs->image.setExternalStorage("CAM_000001.jpg");
  CameraFrame f;
  f.obs = obs;
  f.label = "CAM";
  try {
    loadFrameImage(f, "/nonexistent_dir");
    FAIL() << "expected InputError";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent_dir/CAM_000001.jpg"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace pmap::texture
