// DIR/report/: pictures of the map and of the EM run, and report.html
// (doc/report.md). planar-mapper calls writeReport after its other outputs.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "pmap/products/map_model.h"
#include "pmap/report/em_charts.h"
#include "pmap/report/view_cameras.h"

namespace pmap::report {

struct ReportInputs {
  /// The planar map and the robot path (model.path) to picture.
  const products::MapModel& model;
  /// summary.json as written; the offline EM history is its "history".
  nlohmann::json summary;
  /// Online mode: one row per structure scan (online.csv); empty otherwise.
  std::vector<OnlineScanRow> online_rows;
};

struct ReportOptions {
  MapViewOptions views;       ///< map_perspective.png, map_top.png
  bool render_map = true;     ///< false: no map pictures (noted in the page)
  int chart_width_px = 1000;  ///< em_iterations.png, em_per_scan.png
  int chart_height_px = 720;
  int median_window = 51;  ///< scans in em_per_scan.png's running median

  /// Empty if valid, otherwise the violated rule.
  std::string validate() const;
};

struct ReportResult {
  std::filesystem::path dir;       ///< DIR/report
  std::vector<std::string> files;  ///< written, relative to dir (report.html last)
  /// One line each, also shown in report.html; planar-mapper copies them
  /// into summary.json ("report_warnings").
  std::vector<std::string> warnings;
};

/// Writes DIR/report/: map_perspective.png and map_top.png (offscreen
/// renders), em_iterations.png (when summary has a non-empty history),
/// em_per_scan.png (when there are online rows) and report.html; each file
/// atomically. Pictures of a previous run that this run does not draw are
/// removed. A map that cannot be rendered offscreen, or a malformed history,
/// gives a warning instead of a picture. Throws OutputError when a file or
/// the directory cannot be written, ConfigError for invalid options.
ReportResult writeReport(const std::filesystem::path& dir, const ReportInputs& inputs,
                         const ReportOptions& options = {});

}  // namespace pmap::report
