#include "pmap/sim/poster_art.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <set>

namespace pmap::sim {
namespace {

TEST(PosterArt, DeterministicPerSeedAndDifferentAcrossSeeds) {
  const cv::Mat a = generatePosterImage(400, 280, 11);
  const cv::Mat b = generatePosterImage(400, 280, 11);
  const cv::Mat c = generatePosterImage(400, 280, 12);
  ASSERT_EQ(a.type(), CV_8UC3);
  ASSERT_EQ(a.cols, 400);
  ASSERT_EQ(a.rows, 280);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(a, c, cv::NORM_L1), 0.0);
}

TEST(PosterArt, HasStructure) {
  const cv::Mat img = generatePosterImage(400, 280, 3);
  std::set<int> colours;
  for (int v = 0; v < img.rows; v += 2) {
    for (int u = 0; u < img.cols; u += 2) {
      const cv::Vec3b p = img.at<cv::Vec3b>(v, u);
      colours.insert(p[0] << 16 | p[1] << 8 | p[2]);
    }
  }
  EXPECT_GE(colours.size(), 5u);
  cv::Mat grey, edges;
  cv::cvtColor(img, grey, cv::COLOR_BGR2GRAY);
  cv::Canny(grey, edges, 50, 150);
  EXPECT_GT(cv::countNonZero(edges), img.cols * 4);  // many edges: stripes, shapes, text blocks
}

TEST(PosterArt, TinySizesWork) {
  const cv::Mat img = generatePosterImage(8, 6, 1);
  EXPECT_EQ(img.cols, 8);
  EXPECT_EQ(img.rows, 6);
}

}  // namespace
}  // namespace pmap::sim
