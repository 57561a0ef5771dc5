#include "pmap/report/em_charts.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "pmap/report/chart.h"

namespace pmap::report {
namespace {

/// Pixels in the plot area that are neither background nor grid grey.
int dataPixels(const cv::Mat& img, const cv::Rect& plot) {
  int n = 0;
  const cv::Rect inner(plot.x + 2, plot.y + 2, plot.width - 4, plot.height - 4);
  for (int y = inner.y; y < inner.br().y; ++y) {
    for (int x = inner.x; x < inner.br().x; ++x) {
      const cv::Vec3b p = img.at<cv::Vec3b>(y, x);
      const int spread = std::max({p[0], p[1], p[2]}) - std::min({p[0], p[1], p[2]});
      n += spread > 40 ? 1 : 0;  // coloured, not white / grey / black
    }
  }
  return n;
}

TEST(EmCharts, IterationsChartShowsBothPanels) {
  std::vector<IterationRow> history;
  for (int i = 1; i <= 12; ++i) {
    history.push_back({i, 40.0 - 2.0 * i, 0.5 + 0.03 * i, -1000.0 + i});
  }
  const cv::Size size(900, 700);
  const cv::Mat img = emIterationsChart(history, size);
  ASSERT_EQ(img.size(), size);
  EXPECT_GT(dataPixels(img, chartPlotArea(size, 2, 0)), 500);
  EXPECT_GT(dataPixels(img, chartPlotArea(size, 2, 1)), 500);
}

TEST(EmCharts, PerScanChartShowsBothPanels) {
  std::vector<OnlineScanRow> rows;
  for (int i = 0; i < 400; ++i) {
    rows.push_back({i, 0.5 + (i % 37) * 0.8 + (i % 97 == 0 ? 300.0 : 0.0), i / 10});
  }
  rows[5].em_ms = 0.0;  // not drawable on a log scale, must not break the chart
  const cv::Size size(1000, 720);
  const cv::Mat img = emPerScanChart(rows, size);
  ASSERT_EQ(img.size(), size);
  EXPECT_GT(dataPixels(img, chartPlotArea(size, 2, 0)), 1000);
  EXPECT_GT(dataPixels(img, chartPlotArea(size, 2, 1)), 500);
}

TEST(EmCharts, EmptyInputsGiveEmptyFrames) {
  const cv::Mat a = emIterationsChart({}, {640, 480});
  const cv::Mat b = emPerScanChart({}, {640, 480});
  EXPECT_EQ(a.size(), cv::Size(640, 480));
  EXPECT_EQ(b.size(), cv::Size(640, 480));
  EXPECT_EQ(dataPixels(a, chartPlotArea(a.size(), 2, 1)), 0);
}

}  // namespace
}  // namespace pmap::report
