#include "pmap/sim/camera_rig.h"

#include <gtest/gtest.h>

#include <mrpt/obs/CObservationImage.h>
#include <opencv2/imgcodecs.hpp>

#include "pmap/sim/observation_factory.h"
#include "pmap/sim/world_builder.h"
#include "pmap/sim/world_loader.h"
#include "sim_test_support.h"

namespace pmap::sim {
namespace {

TEST(CameraRig, WritesPostersAndCapturesEveryMount) {
  const auto dir = test::freshDir("camera_rig");
  const World w = buildWorld(parseWorldText(test::tinyWorldJson(), "tiny.json"));
  const std::vector<cv::Mat> posters = writePosterImages(w, 3, dir);
  ASSERT_EQ(posters.size(), 1u);
  const cv::Mat png =
      cv::imread((dir / ("poster_" + std::to_string(w.posters[0].id) + ".png")).string());
  ASSERT_FALSE(png.empty());
  EXPECT_EQ(cv::norm(png, posters[0], cv::NORM_INF), 0.0);
  EXPECT_EQ(png.cols, 100);
  EXPECT_EQ(png.rows, 70);

  const CameraRig rig(w, posters, 3, dir);
  const auto obs = rig.capture(Pose2D{5.0, 0.1, 0.0}, 4, simTimestamp(100.0, 0.05));
  ASSERT_EQ(obs.size(), 2u);
  const auto left = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(obs[0]);
  ASSERT_TRUE(left);
  EXPECT_EQ(left->sensorLabel, "CAMERA_LEFT");
  EXPECT_EQ(left->image.getExternalStorageFile(), "CAMERA_LEFT_000004.jpg");
  const cv::Mat jpg = cv::imread((dir / "CAMERA_LEFT_000004.jpg").string());
  ASSERT_FALSE(jpg.empty());
  EXPECT_EQ(jpg.cols, 64);
  EXPECT_EQ(jpg.rows, 48);
  EXPECT_TRUE(std::filesystem::exists(dir / "CAMERA_RIGHT_000004.jpg"));
}

TEST(CameraRig, LeftCameraSeesThePosterOnTheLeftWall) {
  const World w = buildWorld(parseWorldText(test::tinyWorldJson(), "tiny.json"));
  std::vector<cv::Mat> posters = {cv::Mat(70, 100, CV_8UC3, cv::Scalar(255, 0, 0))};  // blue
  const CameraRig rig(w, posters, 3, test::freshDir("camera_rig_poster"));
  // The poster is centred at x = 6 on the left wall (y = +1), z in [0.8, 1.5].
  const cv::Mat img = rig.renderMount(w.sensors.cameras.mounts[0], Pose2D{6.0, 0.0, 0.0});
  const cv::Vec3f c = img.at<cv::Vec3f>(img.rows / 2 - 5, img.cols / 2);
  EXPECT_GT(c[0], 150.0f);
  EXPECT_LT(c[2], 30.0f);
  const cv::Mat right = rig.renderMount(w.sensors.cameras.mounts[1], Pose2D{6.0, 0.0, 0.0});
  const cv::Vec3f r = right.at<cv::Vec3f>(right.rows / 2, right.cols / 2);
  EXPECT_LT(r[0] - r[2], 100.0f);  // no blue poster on the right
}

}  // namespace
}  // namespace pmap::sim
