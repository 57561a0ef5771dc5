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

/// Poster pixels integrate the pixel's area: across a sharp black/white edge
/// the boundary pixel gets an intermediate value (no point-sampled staircase).
TEST(Renderer, PosterPixelsAreAreaAverages) {
  World w = scene();
  w.clutter.clear();
  cv::Mat half(40, 50, CV_8UC3, cv::Scalar::all(0));
  half.colRange(25, 50).setTo(cv::Scalar::all(255));  // white right half
  const std::vector<cv::Mat> posters = {half};
  const Renderer renderer(w, posters, 1);
  // fx = 32 px at 2 m: 16 px/m. Shift the camera (image +x = world -y) so that
  // the edge (poster u = 0.5 m, world y = 0) falls at u = 32.25: a quarter of
  // pixel 32 is white. Point sampling at the pixel centre would see black.
  RigidTransform cam = forwardCamera();
  cam.translation.y() = (32.25 - kK.cx) / kK.fx * 2.0;
  const cv::Mat img = renderer.render(kK, cam);
  const float left = img.at<cv::Vec3f>(24, 28)[1];
  const float edge = img.at<cv::Vec3f>(24, 32)[1];
  const float right = img.at<cv::Vec3f>(24, 36)[1];
  EXPECT_LT(left, 5.0f);
  EXPECT_GT(right, 200.0f);
  EXPECT_NEAR(edge, 0.25f * right, 0.08f * right);
}

}  // namespace
}  // namespace pmap::sim
