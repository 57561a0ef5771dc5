#include "pmap/texture/hole_fill.h"

#include <gtest/gtest.h>

namespace pmap::texture {
namespace {

cv::Mat accumulator(int rows, int cols) {
  return cv::Mat(rows, cols, CV_32FC4, cv::Scalar::all(0));
}

TEST(HoleFill, SeenTexelsKeepTheirColour) {
  cv::Mat acc = accumulator(8, 8);
  for (int r = 0; r < 8; ++r) {
    for (int c = 0; c < 8; ++c) {
      const float w = 0.5f + 0.1f * c;
      acc.at<cv::Vec4f>(r, c) = cv::Vec4f(w * 10 * r, w * 20 * c, w * 30, w);
    }
  }
  const cv::Mat out = resolveTexture(acc, {0, 0, 0});
  for (int r = 0; r < 8; ++r) {
    for (int c = 0; c < 8; ++c) {
      EXPECT_EQ(out.at<cv::Vec3b>(r, c), cv::Vec3b(10 * r, 20 * c, 30));
    }
  }
}

TEST(HoleFill, HolesTakeTheColourAroundThem) {
  cv::Mat acc = accumulator(33, 17);  // odd sizes: the pyramid's edge cases
  for (int r = 0; r < 33; ++r) {
    for (int c = 0; c < 17; ++c) {
      if (r < 10 || r > 20) {
        acc.at<cv::Vec4f>(r, c) = cv::Vec4f(100, 150, 200, 1);
      }
    }
  }
  const cv::Mat out = resolveTexture(acc, {0, 0, 0});
  EXPECT_EQ(out.at<cv::Vec3b>(15, 8), cv::Vec3b(100, 150, 200));
}

TEST(HoleFill, FillBlendsBetweenDifferentSides) {
  cv::Mat acc = accumulator(1, 64);
  acc.at<cv::Vec4f>(0, 0) = cv::Vec4f(0, 0, 0, 1);
  acc.at<cv::Vec4f>(0, 63) = cv::Vec4f(200, 200, 200, 1);
  const cv::Mat out = resolveTexture(acc, {0, 0, 0});
  EXPECT_LT(out.at<cv::Vec3b>(0, 5)[0], out.at<cv::Vec3b>(0, 58)[0]);
  for (int c = 1; c < 64; ++c) {  // no overshoot
    EXPECT_LE(out.at<cv::Vec3b>(0, c)[0], 200);
  }
}

TEST(HoleFill, NothingSeenGivesTheFallback) {
  const cv::Mat out = resolveTexture(accumulator(5, 3), {10, 20, 30});
  EXPECT_EQ(out.at<cv::Vec3b>(2, 1), cv::Vec3b(10, 20, 30));
}

}  // namespace
}  // namespace pmap::texture
