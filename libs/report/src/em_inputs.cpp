// The report's data inputs: summary.json's history and online.csv.
#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

#include "pmap/common/error.h"
#include "pmap/common/text.h"
#include "pmap/products/output_layout.h"
#include "pmap/report/em_charts.h"

namespace pmap::report {
namespace {

constexpr const char* kSummary = products::OutputLayout::kSummary;

double numberAt(const nlohmann::json& entry, const char* key, std::size_t index) {
  const auto it = entry.find(key);
  if (it == entry.end() || !it->is_number()) {
    throw InputError(std::string(kSummary) + ": history[" + std::to_string(index) + "]: '" + key +
                     "' is missing or not a number");
  }
  return it->get<double>();
}

std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) {
    cells.push_back(cell);
  }
  return cells;
}

}  // namespace

std::vector<IterationRow> historyFromSummary(const nlohmann::json& summary) {
  std::vector<IterationRow> rows;
  const auto it = summary.find("history");
  if (it == summary.end() || it->is_null()) {
    return rows;
  }
  if (!it->is_array()) {
    throw InputError(std::string(kSummary) + ": 'history' is not an array");
  }
  for (std::size_t i = 0; i < it->size(); ++i) {
    const nlohmann::json& e = (*it)[i];
    if (!e.is_object()) {
      throw InputError(std::string(kSummary) + ": history[" + std::to_string(i) +
                       "] is not an object");
    }
    IterationRow r;
    r.iteration = static_cast<int>(numberAt(e, "iteration", i));
    r.surfaces = numberAt(e, "surfaces", i);
    r.explained_fraction = numberAt(e, "explained_fraction", i);
    r.log_posterior = e.contains("log_posterior") ? numberAt(e, "log_posterior", i) : 0.0;
    rows.push_back(r);
  }
  return rows;
}

std::vector<OnlineScanRow> readOnlineCsv(const std::filesystem::path& csv) {
  std::ifstream in(csv);
  if (!in) {
    throw InputError(csv.string() + ": cannot open");
  }
  std::string line;
  if (!std::getline(in, line)) {
    throw InputError(csv.string() + ": empty file (expected a header line)");
  }
  const std::vector<std::string> header = splitCsv(trim(line));
  const auto column = [&](const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) {
      throw InputError(csv.string() + ": line 1: no '" + name + "' column");
    }
    return static_cast<std::size_t>(it - header.begin());
  };
  const std::size_t c_scan = column("scan"), c_ms = column("em_ms"), c_surf = column("surfaces");
  std::vector<OnlineScanRow> rows;
  for (std::size_t number = 2; std::getline(in, line); ++number) {
    if (trim(line).empty()) {
      continue;
    }
    const std::vector<std::string> cells = splitCsv(trim(line));
    const auto cell = [&](std::size_t c) { return c < cells.size() ? cells[c] : std::string(); };
    const auto scan = parseInt(cell(c_scan));
    const auto ms = parseDouble(cell(c_ms));
    const auto surfaces = parseInt(cell(c_surf));
    if (!scan || !ms || !surfaces) {
      throw InputError(csv.string() + ": line " + std::to_string(number) +
                       ": scan, em_ms and surfaces must be numbers");
    }
    rows.push_back({*scan, *ms, static_cast<int>(*surfaces)});
  }
  return rows;
}

}  // namespace pmap::report
