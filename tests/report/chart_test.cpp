#include "pmap/report/chart.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

namespace pmap::report {
namespace {

int nonBackground(const cv::Mat& img, const cv::Rect& area) {
  cv::Mat diff;
  cv::absdiff(img(area), kChartBackground, diff);
  cv::Mat grey;
  cv::cvtColor(diff, grey, cv::COLOR_BGR2GRAY);
  return cv::countNonZero(grey);
}

int colourPixels(const cv::Mat& img, const cv::Rect& area, const cv::Scalar& bgr) {
  cv::Mat mask;
  cv::inRange(img(area), bgr - cv::Scalar(40, 40, 40), bgr + cv::Scalar(40, 40, 40), mask);
  return cv::countNonZero(mask);
}

ChartPanel makePanel(const std::string& title, bool log_y, std::vector<ChartSeries> series) {
  ChartPanel p;
  p.title = title;
  p.x_label = "x";
  p.y_label = "y";
  p.log_y = log_y;
  p.series = std::move(series);
  return p;
}

ChartPanel panel(bool log_y) {
  ChartSeries s{"data", {1, 2, 3, 4, 5}, {1, 10, 100, 30, 3}, {0, 0, 255}, true, 3};
  return makePanel("title", log_y, {s});
}

TEST(Chart, SizeAndDataInsideThePlotArea) {
  const cv::Size size(800, 600);
  const cv::Mat img = drawChart({panel(false), panel(true)}, size);
  ASSERT_EQ(img.size(), size);
  ASSERT_EQ(img.type(), CV_8UC3);
  for (std::size_t i = 0; i < 2; ++i) {
    const cv::Rect plot = chartPlotArea(size, 2, i);
    EXPECT_GT(plot.area(), 0);
    EXPECT_GT(colourPixels(img, plot, {0, 0, 255}), 200) << "panel " << i;
  }
}

TEST(Chart, EmptyAndDegenerateSeriesStillDraw) {
  ChartSeries one{"one", {3}, {7}, {255, 0, 0}, true, 4};
  ChartSeries nonpositive{"log", {1, 2}, {0, -1}, {255, 0, 0}, true, 2};
  const cv::Mat img = drawChart({makePanel("nothing", false, {}), makePanel("single", false, {one}),
                                 makePanel("log", true, {nonpositive})},
                                {600, 900});
  EXPECT_EQ(img.size(), cv::Size(600, 900));
  EXPECT_GT(colourPixels(img, chartPlotArea(img.size(), 3, 1), {255, 0, 0}), 20);
  EXPECT_EQ(colourPixels(img, chartPlotArea(img.size(), 3, 2), {255, 0, 0}), 0);
}

TEST(Chart, AxesAndLabelsAreDrawnOutsideThePlot) {
  const cv::Mat img = drawChart({panel(false)}, {640, 400});
  const cv::Rect plot = chartPlotArea(img.size(), 1, 0);
  EXPECT_GT(nonBackground(img, cv::Rect(0, 0, plot.x, img.rows)), 100);  // y ticks, label
  EXPECT_GT(nonBackground(img, cv::Rect(0, plot.br().y + 2, img.cols, img.rows - plot.br().y - 2)),
            100);  // x ticks, label
}

TEST(Chart, TinySizesAreEnlarged) {
  const cv::Mat img = drawChart({panel(false), panel(false)}, {10, 10});
  EXPECT_GE(img.cols, 320);
  EXPECT_GE(img.rows, 320);
}

}  // namespace
}  // namespace pmap::report
