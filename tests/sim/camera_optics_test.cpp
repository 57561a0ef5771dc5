#include "pmap/sim/camera_optics.h"

#include <gtest/gtest.h>

#include "pmap/sim/poster_art.h"

namespace pmap::sim {
namespace {

cv::Mat posterFloat() {
  cv::Mat f;
  generatePosterImage(200, 140, 11).convertTo(f, CV_32FC3);
  return f;
}

TEST(CameraOptics, BlurReducesTheLaplacianVariance) {
  const cv::Mat sharp = posterFloat();
  const double v0 = laplacianVariance(sharp);
  const double v_psf = laplacianVariance(blurImage(sharp, 0.4, 0.0));
  const double v_defocus = laplacianVariance(blurImage(sharp, 1.5, 0.0));
  const double v_more = laplacianVariance(blurImage(sharp, 2.5, 0.0));
  const double v_motion = laplacianVariance(blurImage(sharp, 0.4, 6.0));
  EXPECT_GT(v0, 100.0);
  EXPECT_LT(v_psf, v0);
  EXPECT_LT(v_defocus, 0.2 * v_psf);  // a blurred frame is clearly less sharp
  EXPECT_LT(v_more, v_defocus);
  EXPECT_LT(v_motion, 0.7 * v_psf);  // only edges across the streak lose
  EXPECT_EQ(laplacianVariance(cv::Mat(20, 20, CV_8UC3, cv::Scalar::all(90))), 0.0);
}

TEST(CameraOptics, BlurKeepsTheInputAndTheMean) {
  const cv::Mat sharp = posterFloat();
  const cv::Mat copy = sharp.clone();
  const cv::Mat blurred = blurImage(sharp, 2.0, 5.5);
  EXPECT_EQ(cv::norm(sharp, copy, cv::NORM_INF), 0.0);  // not written in place
  EXPECT_EQ(blurred.type(), CV_32FC3);
  EXPECT_NEAR(cv::mean(blurred)[1], cv::mean(sharp)[1], 1.0);
  EXPECT_EQ(blurImage(sharp, 0.0, 0.0).data, sharp.data);  // nothing to do
}

TEST(CameraOptics, MotionStreakIsHorizontal) {
  // Vertical stripes (change along x) get smeared; horizontal ones do not.
  cv::Mat vertical(40, 40, CV_32FC1, cv::Scalar(0)), horizontal;
  for (int u = 0; u < 40; u += 4) {
    vertical.colRange(u, u + 2).setTo(200.0f);
  }
  cv::transpose(vertical, horizontal);
  EXPECT_LT(laplacianVariance(blurImage(vertical, 0.0, 6.0)), 0.1 * laplacianVariance(vertical));
  EXPECT_NEAR(laplacianVariance(blurImage(horizontal, 0.0, 6.0)), laplacianVariance(horizontal),
              1e-3 * laplacianVariance(horizontal));
}

TEST(CameraOptics, VignettingFallsOffToTheCorners) {
  const PinholeIntrinsics k = PinholeIntrinsics::fromFov(64, 48, M_PI / 2);
  const cv::Mat v = vignettingMap(k, 0.25);
  ASSERT_EQ(v.type(), CV_32FC1);
  EXPECT_NEAR(v.at<float>(0, 0), 0.75f, 1e-6);
  EXPECT_NEAR(v.at<float>(47, 63), 0.75f, 1e-6);
  EXPECT_GT(v.at<float>(24, 32), 0.999f);
  EXPECT_GT(v.at<float>(24, 0), v.at<float>(0, 0));
  const cv::Mat none = vignettingMap(k, 0.0);
  EXPECT_EQ(cv::norm(none, cv::Mat(48, 64, CV_32FC1, cv::Scalar(1.0)), cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace pmap::sim
