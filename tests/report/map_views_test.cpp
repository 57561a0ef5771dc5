#include "pmap/report/map_views.h"

#include <gtest/gtest.h>

#include "pmap/common/error.h"
#include "report_test_model.h"

namespace pmap::report {
namespace {

MapViewOptions smallViews() {
  MapViewOptions o;
  o.width_px = 640;
  o.height_px = 400;
  return o;
}

TEST(MapViews, RendersBothViewsOffscreen) {
  const MapViews v = renderMapViews(test::corridor(), smallViews());
  ASSERT_TRUE(v.error.empty()) << v.error;
  for (const cv::Mat* img : {&v.perspective, &v.top}) {
    ASSERT_EQ(img->size(), cv::Size(640, 400));
    ASSERT_EQ(img->type(), CV_8UC3);
    EXPECT_GT(test::greyStdDev(*img), 10.0);
  }
}

TEST(MapViews, PerspectiveShowsTheWallsAndTheTexture) {
  const MapViews v = renderMapViews(test::corridor(), smallViews());
  ASSERT_TRUE(v.error.empty()) << v.error;
  const int pixels = v.perspective.rows * v.perspective.cols;
  EXPECT_GT(test::countPixels(v.perspective, test::greenish), pixels / 20);
  EXPECT_GT(test::countPixels(v.perspective, test::magentaish), pixels / 20);
}

TEST(MapViews, TopViewShowsWallTopsAndPath) {
  const MapViews v = renderMapViews(test::corridor(), smallViews());
  ASSERT_TRUE(v.error.empty()) << v.error;
  // 10.5 m across 640 px: a 10 m wall top 3 px wide has about 1800 pixels.
  EXPECT_GT(test::countPixels(v.top, test::greenish), 900);
  EXPECT_GT(test::countPixels(v.top, test::magentaish), 900);
  EXPECT_GT(test::countPixels(v.top, test::orangeish), 600);
  // the ceiling is hidden: the grey floor shows
  EXPECT_GT(test::countPixels(v.top,
                              [](int b, int g, int r) {
                                return std::abs(b - g) < 12 && std::abs(g - r) < 12 && g > 90 &&
                                       g < 235;
                              }),
            640 * 400 / 10);
}

/// Mean pixel position of the pixels near `bgr`.
cv::Point2d centroidOf(const cv::Mat& img, const cv::Vec3b& bgr) {
  cv::Point2d sum(0, 0);
  int n = 0;
  for (int y = 0; y < img.rows; ++y) {
    for (int x = 0; x < img.cols; ++x) {
      const cv::Vec3b p = img.at<cv::Vec3b>(y, x);
      if (cv::norm(cv::Vec3i(p) - cv::Vec3i(bgr), cv::NORM_INF) < 60) {
        sum += cv::Point2d(x, y);
        ++n;
      }
    }
  }
  return n > 50 ? sum / n : cv::Point2d(-1, -1);
}

TEST(MapViews, TextureFollowsTheConvention) {
  // The wall y = 1 seen from x = 0.5 looking +x: c0 is at x = 10 (far), s
  // grows towards the camera; row 0 of the image is the top edge (t = 1).
  auto model = test::corridor();
  model.quads = {model.quads[2]};
  cv::Mat& tex = model.quads[0].texture;
  tex = cv::Mat(64, 64, CV_8UC3);
  const cv::Vec3b red(0, 0, 255), blue(255, 0, 0), yellow(0, 255, 255), cyan(255, 255, 0);
  tex(cv::Rect(0, 0, 32, 32)).setTo(cv::Scalar(red));      // top, far (s < 0.5)
  tex(cv::Rect(32, 0, 32, 32)).setTo(cv::Scalar(blue));    // top, near
  tex(cv::Rect(0, 32, 32, 32)).setTo(cv::Scalar(yellow));  // bottom, far
  tex(cv::Rect(32, 32, 32, 32)).setTo(cv::Scalar(cyan));   // bottom, near
  MapViewOptions o = smallViews();
  const MapViews v = renderMapViews(model, o);
  ASSERT_TRUE(v.error.empty()) << v.error;
  ASSERT_TRUE(v.perspective_on_path);
  // The light dims the texture: compare with the colours as lit.
  const auto lit = [](const cv::Vec3b& c) { return cv::Vec3b(c * 0.75); };
  const cv::Point2d r = centroidOf(v.perspective, lit(red));
  const cv::Point2d b = centroidOf(v.perspective, lit(blue));
  const cv::Point2d y = centroidOf(v.perspective, lit(yellow));
  const cv::Point2d c = centroidOf(v.perspective, lit(cyan));
  for (const auto& p : {r, b, y, c}) {
    ASSERT_GE(p.x, 0) << "a quadrant colour is missing";
  }
  EXPECT_LT(b.y, c.y);  // top above bottom
  EXPECT_LT(r.y, y.y);
  EXPECT_LT(b.x, r.x);  // near (s > 0.5) left of far: the wall is on the left
  EXPECT_LT(c.x, y.x);
}

TEST(MapViews, EmptyModelRendersBackgroundAndGrid) {
  const MapViews v = renderMapViews(products::MapModel{}, smallViews());
  ASSERT_TRUE(v.error.empty()) << v.error;
  EXPECT_EQ(v.perspective.size(), cv::Size(640, 400));
  EXPECT_EQ(v.top.size(), cv::Size(640, 400));
}

TEST(MapViews, InvalidOptionsAreConfigErrors) {
  MapViewOptions o = smallViews();
  o.width_px = 0;
  EXPECT_THROW(renderMapViews(test::corridor(), o), ConfigError);
}

}  // namespace
}  // namespace pmap::report
