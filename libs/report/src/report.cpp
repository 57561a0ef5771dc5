#include "pmap/report/report.h"

#include <algorithm>
#include <opencv2/imgcodecs.hpp>
#include <system_error>

#include "pmap/common/atomic_file.h"
#include "pmap/common/error.h"
#include "pmap/products/output_layout.h"
#include "pmap/products/texture_png.h"
#include "pmap/report/map_views.h"
#include "pmap/report/report_html.h"

namespace pmap::report {
namespace fs = std::filesystem;

namespace {

using products::OutputLayout;
constexpr const char* kPerspective = OutputLayout::kReportPerspective;
constexpr const char* kTop = OutputLayout::kReportTop;
constexpr const char* kIterations = OutputLayout::kReportIterations;
constexpr const char* kPerScan = OutputLayout::kReportPerScan;

/// Collects what the report writes and says.
struct ReportWriter {
  fs::path dir;
  ReportResult result;
  std::vector<ReportImage> images;

  void picture(const char* name, const cv::Mat& image, const std::string& caption) {
    products::writePngAtomically(dir / name, image);
    result.files.push_back(name);
    images.push_back({name, caption});
  }
};

void addMapViews(ReportWriter& w, const ReportInputs& in, const ReportOptions& o) {
  if (!o.render_map) {
    w.result.warnings.push_back("map pictures not rendered (disabled)");
    return;
  }
  const MapViews views = renderMapViews(in.model, o.views);
  if (!views.error.empty()) {
    w.result.warnings.push_back("map pictures not rendered: " + views.error);
    return;
  }
  w.picture(kPerspective, views.perspective,
            views.perspective_on_path
                ? "The planar map in perspective, from the robot path at eye height (orange: "
                  "path)."
                : "The planar map in perspective, from above the map (ceilings hidden; orange: "
                  "path).");
  w.picture(kTop, views.top,
            "The planar map from above (orthographic, ceilings hidden; wall tops and the path "
            "as strips).");
}

void addCharts(ReportWriter& w, const ReportInputs& in, const ReportOptions& o) {
  const cv::Size size(o.chart_width_px, o.chart_height_px);
  try {
    const std::vector<IterationRow> history = historyFromSummary(in.summary);
    if (!history.empty()) {
      w.picture(kIterations, emIterationsChart(history, size),
                "Offline EM: surfaces and explained fraction per iteration.");
    }
  } catch (const InputError& e) {
    w.result.warnings.push_back(std::string("EM iterations chart not drawn: ") + e.what());
  }
  if (!in.online_rows.empty()) {
    w.picture(kPerScan, emPerScanChart(in.online_rows, size, o.median_window),
              "Online EM: time of the EM update per structure scan (log scale) and surfaces.");
  }
}

void removeStalePictures(const ReportWriter& w) {
  for (const char* name : {kPerspective, kTop, kIterations, kPerScan}) {
    if (std::find(w.result.files.begin(), w.result.files.end(), name) == w.result.files.end()) {
      std::error_code ec;
      fs::remove(w.dir / name, ec);
    }
  }
}

}  // namespace

std::string ReportOptions::validate() const {
  if (chart_width_px < 320 || chart_height_px < 320 || chart_width_px > 8192 ||
      chart_height_px > 8192) {
    return "chart_width_px and chart_height_px must be in [320, 8192]";
  }
  if (median_window < 1) {
    return "median_window must be >= 1";
  }
  return views.validate();
}

ReportResult writeReport(const fs::path& dir, const ReportInputs& inputs,
                         const ReportOptions& options) {
  if (const std::string rule = options.validate(); !rule.empty()) {
    throw ConfigError("report options: " + rule);
  }
  ReportWriter w;
  w.dir = dir / OutputLayout::kReportDir;
  ensureWritableDirectory(w.dir);
  w.result.dir = w.dir;
  addMapViews(w, inputs, options);
  addCharts(w, inputs, options);
  removeStalePictures(w);
  writeTextFileAtomically(w.dir / OutputLayout::kReportHtml,
                          reportHtml(inputs.summary, w.images, w.result.warnings));
  w.result.files.push_back(OutputLayout::kReportHtml);
  return w.result;
}

}  // namespace pmap::report
