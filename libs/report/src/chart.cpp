#include "pmap/report/chart.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "pmap/report/chart_ticks.h"

namespace pmap::report {
namespace {

constexpr int kLeft = 96, kRight = 24, kTop = 34, kBottom = 52;
constexpr int kMinWidth = 320, kMinPanelHeight = 160;
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
constexpr double kTextScale = 0.5;
const cv::Scalar kInk{40, 40, 40};
const cv::Scalar kGrid{225, 225, 225};

/// Maps data to pixels inside a plot area (origin at the area's corner).
struct Mapping {
  AxisRange x, y;  ///< y in log10 units when log_y
  bool log_y = false;
  cv::Size area;
  double px(double v) const { return (v - x.lo) / (x.hi - x.lo) * (area.width - 1); }
  double py(double v) const {
    const double u = log_y ? std::log10(v) : v;
    return (area.height - 1) * (1.0 - (u - y.lo) / (y.hi - y.lo));
  }
  bool drawable(double xv, double yv) const {
    return std::isfinite(xv) && std::isfinite(yv) && (!log_y || yv > 0.0);
  }
};

void putText(cv::Mat& img, const std::string& text, cv::Point org, double scale = kTextScale) {
  cv::putText(img, text, org, kFont, scale, kInk, 1, cv::LINE_AA);
}

cv::Size textSize(const std::string& text, double scale = kTextScale) {
  int baseline = 0;
  return cv::getTextSize(text, kFont, scale, 1, &baseline);
}

/// Text rotated by 90 degrees (reading upwards), centred on `centre`.
void putVerticalText(cv::Mat& img, const std::string& text, cv::Point centre) {
  const cv::Size ts = textSize(text);
  cv::Mat strip(ts.height + 8, ts.width + 4, CV_8UC3, kChartBackground);
  putText(strip, text, {2, ts.height + 2});
  cv::Mat rotated;
  cv::rotate(strip, rotated, cv::ROTATE_90_COUNTERCLOCKWISE);
  cv::Rect dst(centre.x - rotated.cols / 2, centre.y - rotated.rows / 2, rotated.cols,
               rotated.rows);
  dst &= cv::Rect(0, 0, img.cols, img.rows);
  rotated(cv::Rect(0, 0, dst.width, dst.height)).copyTo(img(dst));
}

Mapping panelMapping(const ChartPanel& panel, cv::Size area) {
  double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo;
  double y_lo = x_lo, y_hi = -x_lo;
  Mapping m;
  m.log_y = panel.log_y;
  for (const auto& s : panel.series) {
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      if (m.drawable(s.x[i], s.y[i])) {
        x_lo = std::min(x_lo, s.x[i]);
        x_hi = std::max(x_hi, s.x[i]);
        y_lo = std::min(y_lo, s.y[i]);
        y_hi = std::max(y_hi, s.y[i]);
      }
    }
  }
  // a 2 % margin keeps markers at the extremes off the frame
  const double y_pad = panel.log_y ? 0.0 : 0.02 * (y_hi - y_lo);
  y_lo = panel.y_min.value_or(y_lo - y_pad);
  y_hi = panel.y_max.value_or(y_hi + y_pad);
  m.x = paddedRange(x_lo, x_hi);
  m.y = panel.log_y ? logRange(y_lo, y_hi) : niceRange(y_lo, y_hi, 5);
  if (panel.y_min && panel.y_max && !panel.log_y && *panel.y_max > *panel.y_min) {
    m.y = {*panel.y_min, *panel.y_max};
  }
  m.area = area;
  return m;
}

void drawAxes(cv::Mat& img, const cv::Rect& plot, const Mapping& m, const ChartPanel& panel) {
  const std::vector<double> y_ticks = panel.log_y ? logTicks(m.y) : linearTicks(m.y, 5);
  for (const double v : y_ticks) {
    const int y = plot.y + static_cast<int>(std::lround(m.py(v)));
    cv::line(img, {plot.x, y}, {plot.br().x - 1, y}, kGrid, 1);
    cv::line(img, {plot.x - 5, y}, {plot.x, y}, kInk, 1);
    const std::string label = tickLabel(v);
    putText(img, label, {plot.x - 8 - textSize(label).width, y + 5});
  }
  for (const double v : linearTicks(m.x, 8)) {
    if (panel.integer_x && std::abs(v - std::round(v)) > 1e-9) {
      continue;
    }
    const int x = plot.x + static_cast<int>(std::lround(m.px(v)));
    cv::line(img, {x, plot.y}, {x, plot.br().y - 1}, kGrid, 1);
    cv::line(img, {x, plot.br().y}, {x, plot.br().y + 5}, kInk, 1);
    const std::string label = tickLabel(v);
    putText(img, label, {x - textSize(label).width / 2, plot.br().y + 20});
  }
  cv::rectangle(img, plot, kInk, 1);
  putText(img, panel.title, {plot.x, plot.y - 10}, 0.55);
  putText(img, panel.x_label,
          {plot.x + (plot.width - textSize(panel.x_label).width) / 2, plot.br().y + 42});
  putVerticalText(img, panel.y_label, {plot.x - kLeft + 14, plot.y + plot.height / 2});
}

void drawSeries(cv::Mat& area, const Mapping& m, const ChartSeries& s) {
  std::vector<cv::Point> run;
  const auto flush = [&] {
    if (s.line && run.size() > 1) {
      cv::polylines(area, run, false, s.color, 2, cv::LINE_AA);
    }
    run.clear();
  };
  for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
    if (!m.drawable(s.x[i], s.y[i])) {
      flush();
      continue;
    }
    const cv::Point p(static_cast<int>(std::lround(m.px(s.x[i]))),
                      static_cast<int>(std::lround(m.py(s.y[i]))));
    run.push_back(p);
    if (s.dot_radius_px > 0) {
      cv::circle(area, p, s.dot_radius_px, s.color, cv::FILLED, cv::LINE_AA);
    }
  }
  flush();
}

void drawSwatch(cv::Mat& img, cv::Point left, const ChartSeries& s) {
  if (s.line) {
    cv::line(img, left, left + cv::Point(24, 0), s.color, 2, cv::LINE_AA);
  }
  if (s.dot_radius_px > 0) {
    cv::circle(img, left + cv::Point(12, 0), s.dot_radius_px + 1, s.color, cv::FILLED, cv::LINE_AA);
  }
}

/// One row right-aligned above the plot, beside the title: the data stays
/// uncovered.
void drawLegend(cv::Mat& img, const cv::Rect& plot, const std::vector<ChartSeries>& series) {
  constexpr int kSwatch = 30, kGap = 18;
  int width = 0;
  for (const auto& s : series) {
    width += kSwatch + textSize(s.label).width + kGap;
  }
  cv::Point at(plot.br().x - width + kGap, plot.y - 10);
  for (const auto& s : series) {
    drawSwatch(img, at + cv::Point(0, -5), s);
    putText(img, s.label, at + cv::Point(kSwatch, 0));
    at.x += kSwatch + textSize(s.label).width + kGap;
  }
}

bool hasData(const Mapping& m, const ChartSeries& s) {
  for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
    if (m.drawable(s.x[i], s.y[i])) {
      return true;
    }
  }
  return false;
}

void drawPanel(cv::Mat& img, const cv::Rect& plot, const ChartPanel& panel) {
  const Mapping m = panelMapping(panel, plot.size());
  drawAxes(img, plot, m, panel);
  cv::Mat area = img(plot);
  std::vector<ChartSeries> shown;
  for (const auto& s : panel.series) {
    if (hasData(m, s)) {
      drawSeries(area, m, s);
      shown.push_back(s);
    }
  }
  cv::rectangle(img, plot, kInk, 1);
  if (shown.empty()) {
    const cv::Size ts = textSize("no data");
    putText(img, "no data", {plot.x + (plot.width - ts.width) / 2, plot.y + plot.height / 2});
  } else {
    drawLegend(img, plot, shown);
  }
}

}  // namespace

cv::Rect chartPlotArea(cv::Size size, std::size_t panels, std::size_t index) {
  const int n = static_cast<int>(std::max<std::size_t>(1, panels));
  const int panel_height = size.height / n;
  const int top = panel_height * static_cast<int>(index);
  return {kLeft, top + kTop, size.width - kLeft - kRight, panel_height - kTop - kBottom};
}

cv::Mat drawChart(const std::vector<ChartPanel>& panels, cv::Size size) {
  const int n = static_cast<int>(std::max<std::size_t>(1, panels.size()));
  size.width = std::max(size.width, kMinWidth);
  size.height = std::max(size.height, kMinPanelHeight * n);
  cv::Mat img(size, CV_8UC3, kChartBackground);
  for (std::size_t i = 0; i < panels.size(); ++i) {
    drawPanel(img, chartPlotArea(size, panels.size(), i), panels[i]);
  }
  return img;
}

}  // namespace pmap::report
