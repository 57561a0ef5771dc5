#include "pmap/report/report_html.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "pmap/common/text.h"

namespace pmap::report {
namespace {

using nlohmann::json;

struct RowSpec {
  const char* label;
  const char* pointer;  ///< JSON pointer into summary.json
  const char* unit;
};

// The key numbers, in the order the table shows them (doc/outputs.md).
const RowSpec kRows[] = {
    {"mode", "/mode", ""},
    {"structure scans", "/scans", ""},
    {"points", "/points", ""},
    {"surfaces (rectangles)", "/surfaces", ""},
    {"fine triangles", "/fine_triangles", ""},
    {"explained fraction", "/explained_fraction", ""},
    {"raw triangles", "/raw_triangles", ""},
    {"map triangles", "/map_triangles", ""},
    {"compression (raw / map triangles)", "/compression", ""},
    {"EM iterations", "/iterations", ""},
    {"termination", "/termination", ""},
    {"EM message", "/em_message", ""},
    {"EM time per iteration", "/ms_per_iteration", "ms"},
    {"EM update per scan, p50", "/em_per_scan_ms/p50", "ms"},
    {"EM update per scan, p99", "/em_per_scan_ms/p99", "ms"},
    {"EM update per scan, max", "/em_per_scan_ms/max", "ms"},
    {"pose stage per scan, p50", "/pose_per_scan_ms/p50", "ms"},
    {"pose stage per scan, p99", "/pose_per_scan_ms/p99", "ms"},
    {"recorded duration", "/duration_s", "s"},
    {"time: total (the stages below)", "/timing_s/total", "s"},
    {"time: read", "/timing_s/read", "s"},
    {"time: poses", "/timing_s/pose", "s"},
    {"time: map", "/timing_s/map", "s"},
    {"time: EM", "/timing_s/em", "s"},
    {"time: refinement", "/timing_s/refine", "s"},
    {"time: textures", "/timing_s/texture", "s"},
    {"time: write", "/timing_s/write", "s"},
    {"time: other (set-up, configuration)", "/timing_s/other", "s"},
    {"realtime factor", "/realtime_factor", ""},
};

/// The value as text; empty for null, objects and arrays.
std::string valueText(const json& v) {
  if (v.is_boolean()) {
    return v.get<bool>() ? "yes" : "no";
  }
  if (v.is_number_integer() || v.is_number_unsigned()) {
    return v.dump();
  }
  if (v.is_number()) {
    return formatNumber(v.get<double>());
  }
  if (v.is_string()) {
    return v.get<std::string>();
  }
  return {};
}

const char* kStyle =
    "body{font-family:sans-serif;margin:2em;color:#222;max-width:1320px}"
    "table{border-collapse:collapse;margin:1em 0}"
    "td{border-bottom:1px solid #ddd;padding:3px 12px}td.v{text-align:right}"
    ".warning{background:#fff3cd;border:1px solid #e0c060;padding:6px 10px;margin:4px 0}"
    "figure{margin:1.5em 0}img{max-width:100%;border:1px solid #ccc}"
    "figcaption{color:#555;margin-top:4px}";

}  // namespace

std::string formatNumber(double value) {
  if (!std::isfinite(value)) {
    return value != value ? "nan" : (value > 0 ? "inf" : "-inf");
  }
  if (value == std::round(value) && std::abs(value) < 1e15) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.0f", value);
    return buf;
  }
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", value);
  return buf;
}

std::vector<std::pair<std::string, std::string>> summaryRows(const json& summary) {
  std::vector<std::pair<std::string, std::string>> rows;
  for (const RowSpec& spec : kRows) {
    const json::json_pointer ptr(spec.pointer);
    if (!summary.is_object() || !summary.contains(ptr)) {
      continue;
    }
    std::string text = valueText(summary.at(ptr));
    if (text.empty()) {
      continue;
    }
    if (*spec.unit != '\0') {
      text += std::string(" ") + spec.unit;
    }
    rows.emplace_back(spec.label, text);
  }
  return rows;
}

std::string reportHtml(const json& summary, const std::vector<ReportImage>& images,
                       const std::vector<std::string>& warnings) {
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
       << "<title>planar-mapper report</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n"
       << "<h1>planar-mapper report</h1>\n";
  for (const std::string& w : warnings) {
    html << "<p class=\"warning\">warning: " << escapeHtml(w) << "</p>\n";
  }
  html << "<h2>Summary</h2>\n<table>\n";
  for (const auto& [label, value] : summaryRows(summary)) {
    html << "<tr><td>" << escapeHtml(label) << "</td><td class=\"v\">" << escapeHtml(value)
         << "</td></tr>\n";
  }
  html << "</table>\n";
  for (const ReportImage& image : images) {
    html << "<figure>\n<img src=\"" << escapeHtml(image.file) << "\" alt=\""
         << escapeHtml(image.caption) << "\">\n<figcaption>" << escapeHtml(image.caption)
         << "</figcaption>\n</figure>\n";
  }
  html << "</body>\n</html>\n";
  return html.str();
}

}  // namespace pmap::report
