#include "pmap/report/em_charts.h"

#include <algorithm>
#include <string>

#include "pmap/report/chart.h"

namespace pmap::report {
namespace {

const cv::Scalar kBlue{180, 110, 30};
const cv::Scalar kOrange{20, 120, 240};
const cv::Scalar kGreen{60, 150, 40};
const cv::Scalar kSoftBlue{215, 175, 130};

/// Median of the window centred on each value (shorter at the ends).
std::vector<double> runningMedian(const std::vector<double>& v, int window) {
  const std::size_t half = static_cast<std::size_t>(std::max(1, window) / 2);
  std::vector<double> out(v.size());
  std::vector<double> buf;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::size_t a = i >= half ? i - half : 0;
    const std::size_t b = std::min(v.size(), i + half + 1);
    buf.assign(v.begin() + static_cast<std::ptrdiff_t>(a),
               v.begin() + static_cast<std::ptrdiff_t>(b));
    auto mid = buf.begin() + static_cast<std::ptrdiff_t>(buf.size() / 2);
    std::nth_element(buf.begin(), mid, buf.end());
    out[i] = *mid;
  }
  return out;
}

ChartPanel panel(const char* title, const char* x_label, const char* y_label) {
  ChartPanel p;
  p.title = title;
  p.x_label = x_label;
  p.y_label = y_label;
  p.integer_x = true;
  return p;
}

}  // namespace

cv::Mat emIterationsChart(const std::vector<IterationRow>& history, cv::Size size) {
  ChartSeries surfaces{"surfaces", {}, {}, kBlue, true, 4};
  ChartSeries explained{"explained fraction", {}, {}, kOrange, true, 4};
  for (const auto& r : history) {
    surfaces.x.push_back(r.iteration);
    surfaces.y.push_back(r.surfaces);
    explained.x.push_back(r.iteration);
    explained.y.push_back(r.explained_fraction);
  }
  ChartPanel top = panel("Offline EM: surfaces per iteration", "EM iteration", "surfaces");
  top.y_min = 0.0;
  top.series = {surfaces};
  ChartPanel bottom = panel("Offline EM: share of points explained by a surface", "EM iteration",
                            "explained fraction");
  bottom.series = {explained};
  return drawChart({top, bottom}, size);
}

cv::Mat emPerScanChart(const std::vector<OnlineScanRow>& rows, cv::Size size, int median_window) {
  ChartSeries per_scan{"EM update per scan", {}, {}, kSoftBlue, false, 2};
  ChartSeries surfaces{"surfaces", {}, {}, kGreen, true, 0};
  for (const auto& r : rows) {
    per_scan.x.push_back(static_cast<double>(r.scan));
    per_scan.y.push_back(r.em_ms);
    surfaces.x.push_back(static_cast<double>(r.scan));
    surfaces.y.push_back(r.surfaces);
  }
  ChartSeries median{"running median (" + std::to_string(median_window) + " scans)",
                     per_scan.x,
                     runningMedian(per_scan.y, median_window),
                     kOrange,
                     true,
                     0};
  ChartPanel top =
      panel("Online EM: time of the EM update per scan", "structure scan", "EM time (ms)");
  top.log_y = true;
  top.series = {per_scan, median};
  ChartPanel bottom = panel("Online EM: surfaces in the map", "structure scan", "surfaces");
  bottom.y_min = 0.0;
  bottom.series = {surfaces};
  return drawChart({top, bottom}, size);
}

}  // namespace pmap::report
