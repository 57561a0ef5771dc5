// A small chart drawer on OpenCV (lines, dots, axes, ticks, labels, legend)
// for the report's pictures; panels are stacked vertically.
#pragma once

#include <cstddef>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

namespace pmap::report {

struct ChartSeries {
  std::string label;  ///< legend text
  std::vector<double> x, y;
  cv::Scalar color{180, 90, 20};  ///< BGR
  bool line = true;               ///< join consecutive points
  int dot_radius_px = 0;          ///< 0: no dots
};

struct ChartPanel {
  std::string title, x_label, y_label;
  bool log_y = false;                  ///< log10 y axis; values <= 0 are not drawn
  bool integer_x = false;              ///< x ticks at whole numbers only (iterations, scans)
  std::optional<double> y_min, y_max;  ///< fixed y limits (else from the data)
  std::vector<ChartSeries> series;
};

/// White background the charts are drawn on (BGR).
inline const cv::Scalar kChartBackground{255, 255, 255};

/// The plot area (inside the axes) of panel `index` of `panels` stacked
/// panels in an image of `size`.
cv::Rect chartPlotArea(cv::Size size, std::size_t panels, std::size_t index);

/// Draws the panels into a new 8-bit BGR image of `size` (at least
/// 320 x 160 per panel; smaller sizes are enlarged to that).
cv::Mat drawChart(const std::vector<ChartPanel>& panels, cv::Size size);

}  // namespace pmap::report
