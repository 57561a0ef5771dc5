// report.html: the pictures and the key numbers of summary.json, one
// self-contained page (images referenced relatively, no scripts, no network).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace pmap::report {

struct ReportImage {
  std::string file;  ///< relative to report.html
  std::string caption;
};

/// (label, formatted value) rows of the key numbers present in `summary`:
/// mode, scans, points, surfaces, fine triangles, explained fraction,
/// compression, iterations / termination, timings, realtime factor, EM and
/// pose per-scan percentiles. Absent keys give no row.
std::vector<std::pair<std::string, std::string>> summaryRows(const nlohmann::json& summary);

/// A number as the report prints it: integers in full, others with 4
/// significant digits (e.g. 0.9123, 12.35, 1.235e+04).
std::string formatNumber(double value);

/// The page: title, warnings (one line each), the summary table, then each
/// image with its caption. Text is HTML-escaped.
std::string reportHtml(const nlohmann::json& summary, const std::vector<ReportImage>& images,
                       const std::vector<std::string>& warnings);

}  // namespace pmap::report
