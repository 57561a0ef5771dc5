// The report's EM charts (doc/report.md): the offline EM iterations (the
// paper's Fig. 6) and the online EM time and map size per scan.
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <vector>

namespace pmap::report {

/// One entry of summary.json's `history` (offline EM, per iteration).
struct IterationRow {
  int iteration = 0;
  double surfaces = 0;
  double explained_fraction = 0;
  double log_posterior = 0;
};

/// One row of online.csv (online EM, per structure scan).
struct OnlineScanRow {
  std::int64_t scan = 0;  ///< structure scan index in the file
  double em_ms = 0;       ///< the EM update alone
  int surfaces = 0;       ///< surfaces after the update
};

/// summary["history"]; empty when absent. Throws InputError naming the entry
/// and key when an entry lacks a numeric iteration, surfaces or
/// explained_fraction (log_posterior is optional).
std::vector<IterationRow> historyFromSummary(const nlohmann::json& summary);

/// Reads the scan, em_ms and surfaces columns of online.csv (found by their
/// header names). Throws InputError naming the file and line.
std::vector<OnlineScanRow> readOnlineCsv(const std::filesystem::path& csv);

/// Two panels against the iteration: surfaces, explained fraction.
cv::Mat emIterationsChart(const std::vector<IterationRow>& history, cv::Size size);

/// Two panels against the scan index: EM time per scan (log scale, with a
/// running median over `median_window` scans) and surfaces.
cv::Mat emPerScanChart(const std::vector<OnlineScanRow>& rows, cv::Size size,
                       int median_window = 51);

}  // namespace pmap::report
