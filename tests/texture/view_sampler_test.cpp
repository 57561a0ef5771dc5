#include "pmap/texture/view_sampler.h"

#include <gtest/gtest.h>

namespace pmap::texture {
namespace {

// A 9 x 7 image whose channels are affine and quadratic in x and y.
cv::Mat ramps() {
  cv::Mat img(7, 9, CV_8UC3);
  for (int y = 0; y < img.rows; ++y) {
    for (int x = 0; x < img.cols; ++x) {
      img.at<cv::Vec3b>(y, x) =
          cv::Vec3b(static_cast<uchar>(10 + 20 * x), static_cast<uchar>(30 + 25 * y),
                    static_cast<uchar>(2 * (x - 4) * (x - 4) + 3 * y * y));
    }
  }
  return img;
}

TEST(SampleBicubic, PixelCentresGiveThePixels) {
  const cv::Mat img = ramps();
  for (int y = 0; y < img.rows; ++y) {
    for (int x = 0; x < img.cols; ++x) {
      const cv::Vec3f s = sampleBicubic(img, x, y);
      const cv::Vec3b p = img.at<cv::Vec3b>(y, x);
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(s[k], p[k], 1e-4) << x << "," << y;
      }
    }
  }
}

// Keys' kernel (a = -0.5) reproduces polynomials up to degree 2 exactly away
// from the border: the ramps and the parabola between pixels.
TEST(SampleBicubic, ReproducesRampsAndParabolasBetweenPixels) {
  const cv::Mat img = ramps();
  for (const double x : {2.25, 3.5, 4.75, 5.1}) {
    for (const double y : {2.3, 3.5, 3.9}) {
      const cv::Vec3f s = sampleBicubic(img, x, y);
      EXPECT_NEAR(s[0], 10 + 20 * x, 1e-3);
      EXPECT_NEAR(s[1], 30 + 25 * y, 1e-3);
      EXPECT_NEAR(s[2], 2 * (x - 4) * (x - 4) + 3 * y * y, 1e-3);
    }
  }
}

TEST(SampleBicubic, OvershootAtAnEdgeIsClampedAndBordersRepeat) {
  cv::Mat img(4, 4, CV_8UC3, cv::Scalar::all(0));
  img.colRange(2, 4).setTo(cv::Scalar::all(255));  // a step from 0 to 255
  const cv::Vec3f before = sampleBicubic(img, 0.5, 1.5);
  const cv::Vec3f after = sampleBicubic(img, 2.5, 1.5);
  EXPECT_GE(before[0], 0.f);
  EXPECT_LE(after[0], 255.f);
  const cv::Vec3f corner = sampleBicubic(img, 3.0, 3.0);
  EXPECT_NEAR(corner[0], 255.f, 1e-3);
}

}  // namespace
}  // namespace pmap::texture
