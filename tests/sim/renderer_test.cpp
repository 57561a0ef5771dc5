#include "pmap/sim/renderer.h"

#include <gtest/gtest.h>

#include "pmap/sim/poster_art.h"

namespace pmap::sim {
namespace {

using Eigen::Vector3d;

const PinholeIntrinsics kK = PinholeIntrinsics::fromFov(64, 48, M_PI / 2);

/// A wall 2 m in front of a forward camera at the origin (optical axis +x),
/// with a poster on it, and a bin 1 m in front of the camera, on its left.
World scene() {
  World w;
  Surface wall;
  wall.id = 0;
  wall.kind = "wall";
  wall.rect = Rectangle3::facing(Vector3d(2, 3, -2), Vector3d(2, -3, -2), Vector3d(2, 3, 3),
                                 Vector3d(0, 0, 0));
  wall.poster_indices = {0};
  w.surfaces.push_back(wall);
  Poster p;
  p.id = 2;
  p.wall_id = 0;
  p.wall_index = 0;
  p.pixels_per_m = 50;
  p.width_px = 50;
  p.height_px = 40;
  p.rect = Rectangle3::facing(Vector3d(2, -0.5, -0.4), Vector3d(2, 0.5, -0.4),
                              Vector3d(2, -0.5, 0.4), Vector3d(0, 0, 0));
  w.posters.push_back(p);
  Clutter bin;
  bin.id = 1;
  bin.kind = "bin";
  bin.cylinder = VerticalCylinder{Eigen::Vector2d(1.0, 0.7), 0.15, -2.0, 2.0};
  w.clutter.push_back(bin);
  return w;
}

RigidTransform forwardCamera() {
  return toTransform(Pose6D{0, 0, 0, -M_PI / 2, 0, -M_PI / 2});
}

TEST(Renderer, DrawsPosterWallAndOccludingBin) {
  const World w = scene();
  const std::vector<cv::Mat> posters = {cv::Mat(40, 50, CV_8UC3, cv::Scalar(0, 0, 255))};
  const Renderer renderer(w, posters, 1);
  const cv::Mat img = renderer.render(kK, forwardCamera());
  ASSERT_EQ(img.type(), CV_32FC3);
  // Centre pixel: the red poster (BGR), shaded by the headlight term only.
  const cv::Vec3f centre = img.at<cv::Vec3f>(24, 32);
  EXPECT_LT(centre[0], 10.0f);
  EXPECT_GT(centre[2], 150.0f);
  // A corner pixel: painted wall, light and neutral.
  const cv::Vec3f corner = img.at<cv::Vec3f>(2, 60);
  EXPECT_GT(corner[0], 100.0f);
  EXPECT_GT(corner[1], 100.0f);
  // The bin is at y = 0.7 (left of the optical axis): green, on the image left.
  const cv::Vec3f bin = img.at<cv::Vec3f>(24, 32 - static_cast<int>(kK.fx * 0.7 / 1.0) + 2);
  EXPECT_GT(bin[1], bin[0]);
  EXPECT_GT(bin[1], bin[2]);
}

TEST(Renderer, BackgroundWhereNothingIsHit) {
  World w = scene();
  const std::vector<cv::Mat> posters = {cv::Mat(40, 50, CV_8UC3, cv::Scalar(0, 0, 255))};
  const Renderer renderer(w, posters, 1);
  // Looking backwards there is nothing.
  const cv::Mat img = renderer.render(kK, toTransform(Pose6D{0, 0, 0, M_PI / 2, 0, -M_PI / 2}));
  EXPECT_EQ(img.at<cv::Vec3f>(24, 32), cv::Vec3f(20.0f, 20.0f, 20.0f));
}

TEST(Renderer, FinishImageIsDeterministicAndNoisy) {
  const cv::Mat flat(48, 64, CV_32FC3, cv::Scalar(100, 100, 100));
  const cv::Mat a = finishImage(flat, 2.0, 5);
  const cv::Mat b = finishImage(flat, 2.0, 5);
  ASSERT_EQ(a.type(), CV_8UC3);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
  cv::Scalar mean, stddev;
  cv::meanStdDev(a.reshape(1), mean, stddev);
  EXPECT_NEAR(mean[0], 100.0, 0.5);
  EXPECT_NEAR(stddev[0], 2.0, 0.3);
  EXPECT_EQ(cv::norm(finishImage(flat, 0.0, 5), cv::Mat(48, 64, CV_8UC3, cv::Scalar::all(100)),
                     cv::NORM_INF),
            0.0);
}

}  // namespace
}  // namespace pmap::sim
