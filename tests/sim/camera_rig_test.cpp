#include "pmap/sim/camera_rig.h"

#include <gtest/gtest.h>

#include <mrpt/obs/CObservationImage.h>
#include <opencv2/imgcodecs.hpp>

#include "pmap/sim/ground_truth_json.h"
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
  const Capture capture = rig.capture(Pose2D{5.0, 0.1, 0.0}, 4, simTimestamp(100.0, 0.05));
  const auto& obs = capture.observations;
  ASSERT_EQ(obs.size(), 2u);
  ASSERT_EQ(capture.records.size(), 2u);
  EXPECT_EQ(capture.records[0].file, "CAMERA_LEFT_000004.jpg");
  EXPECT_EQ(capture.records[1].label, "CAMERA_RIGHT");
  EXPECT_EQ(capture.records[0].index, 4);
  EXPECT_EQ(capture.records[0].timestamp_s, mrpt::Clock::toDouble(obs[0]->timestamp));
  const FrameEffects fx = rig.frameEffects("CAMERA_LEFT", 4);
  EXPECT_EQ(capture.records[0].effects.exposure.gain, fx.exposure.gain);
  EXPECT_EQ(capture.records[0].effects.blur_sigma_px, fx.blur_sigma_px);
  const auto left = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(obs[0]);
  ASSERT_TRUE(left);
  EXPECT_EQ(left->sensorLabel, "CAMERA_LEFT");
  EXPECT_EQ(left->image.getExternalStorageFile(), "CAMERA_LEFT_000004.jpg");
  const cv::Mat jpg = cv::imread((dir / "CAMERA_LEFT_000004.jpg").string());
  ASSERT_FALSE(jpg.empty());
  EXPECT_EQ(jpg.cols, 64);
  EXPECT_EQ(jpg.rows, 48);
  EXPECT_TRUE(std::filesystem::exists(dir / "CAMERA_RIGHT_000004.jpg"));
  // The JPEG is the developed frame (up to JPEG's loss).
  const DevelopedFrame frame =
      rig.developMount(w.sensors.cameras.mounts[0], Pose2D{5.0, 0.1, 0.0}, 4);
  EXPECT_LT(cv::norm(jpg, frame.image, cv::NORM_L1) / jpg.total() / 3.0, 5.0);
}

TEST(CameraRig, FramesOfOneCameraDifferInExposureAndBlur) {
  const World w = buildWorld(parseWorldText(test::tinyWorldJson(), "tiny.json"));
  const std::vector<cv::Mat> posters = {cv::Mat(70, 100, CV_8UC3, cv::Scalar(40, 200, 120))};
  const CameraRig rig(w, posters, 3, test::freshDir("camera_rig_frames"));
  double gain_lo = 10.0, gain_hi = 0.0;
  int blurred = 0;
  for (int i = 0; i < 40; ++i) {
    const FrameEffects fx = rig.frameEffects("CAMERA_LEFT", i);
    gain_lo = std::min(gain_lo, fx.exposure.gain);
    gain_hi = std::max(gain_hi, fx.exposure.gain);
    blurred += fx.blurred ? 1 : 0;
  }
  EXPECT_GE(gain_lo, 0.8);
  EXPECT_LE(gain_hi, 1.2);
  EXPECT_GT(gain_hi - gain_lo, 0.2);
  EXPECT_GT(blurred, 3);
  EXPECT_LT(blurred, 25);
  EXPECT_NE(rig.frameEffects("CAMERA_LEFT", 0).exposure.gain,
            rig.frameEffects("CAMERA_RIGHT", 0).exposure.gain);
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

/// doc/ground-truth.md: poster pixel (col, row) has its centre at
/// c0 + (col + 0.5) / ppm * u + (H - (row + 0.5) / ppm) * v, pixel (0, 0) at c3.
TEST(CameraRig, PosterImageMapsOntoItsCornersAsDocumented) {
  const World w = buildWorld(parseWorldText(test::tinyWorldJson(), "tiny.json"));
  cv::Mat art(70, 100, CV_8UC3, cv::Scalar(255, 0, 0));        // blue
  art(cv::Rect(0, 0, 50, 35)).setTo(cv::Scalar(0, 0, 255));    // red top-left quadrant
  art(cv::Rect(50, 35, 50, 35)).setTo(cv::Scalar(0, 255, 0));  // green bottom-right
  const std::vector<cv::Mat> posters = {art};
  const CameraRig rig(w, posters, 3, test::freshDir("camera_rig_mapping"));
  const OrderedJson gt = postersJson(w, "run_Images")[0];
  auto corner = [&](int i) {
    const auto& c = gt["corners"][static_cast<std::size_t>(i)];
    return Eigen::Vector3d(c[0].get<double>(), c[1].get<double>(), c[2].get<double>());
  };
  const double ppm = gt["pixels_per_m"].get<double>();
  const Eigen::Vector3d c0 = corner(0);
  const Eigen::Vector3d u = (corner(1) - c0).normalized();
  const Eigen::Vector3d v = (corner(3) - c0).normalized();
  const double height = (corner(3) - c0).norm();
  const Pose2D robot{6.0, 0.0, 0.0};
  const CameraMount& left = w.sensors.cameras.mounts[0];
  const cv::Mat img = rig.renderMount(left, robot);
  const RigidTransform cam = compose(toTransform(robot), toTransform(cameraMountPose(left)));
  auto colourAt = [&](double col, double row) {
    const Eigen::Vector3d p = c0 + (col + 0.5) / ppm * u + (height - (row + 0.5) / ppm) * v;
    const auto px = projectPoint(rig.intrinsics(), cam, p);
    EXPECT_TRUE(px);
    return img.at<cv::Vec3f>(static_cast<int>(std::lround(px->y())),
                             static_cast<int>(std::lround(px->x())));
  };
  const cv::Vec3f top_left = colourAt(20, 12);
  EXPECT_GT(top_left[2], 100.0f);  // red
  EXPECT_LT(top_left[0], 30.0f);
  const cv::Vec3f bottom_right = colourAt(80, 58);
  EXPECT_GT(bottom_right[1], 100.0f);  // green
  EXPECT_LT(bottom_right[2], 30.0f);
  const cv::Vec3f top_right = colourAt(80, 12);
  EXPECT_GT(top_right[0], 100.0f);  // blue
  EXPECT_LT(top_right[2], 30.0f);
  // Pixel (0, 0) touches corner c3 (top-left).
  const Eigen::Vector3d p00 = c0 + 0.5 / ppm * u + (height - 0.5 / ppm) * v;
  EXPECT_LT((p00 - corner(3)).norm(), 1.0 / ppm);
}

}  // namespace
}  // namespace pmap::sim
