#include "pmap/report/report_html.h"

#include <gtest/gtest.h>

#include <map>

namespace pmap::report {
namespace {

const char* kSummary = R"({
  "mode": "offline", "scans": 240, "points": 123456, "surfaces": 42, "fine_triangles": 7,
  "explained_fraction": 0.91234, "compression": 812.5, "iterations": 9,
  "termination": "converged", "timing_s": {"total": 12.5, "em": 3.25},
  "realtime_factor": 4.125, "em_per_scan_ms": {"p50": 1.5, "p99": 20.25, "max": null}
})";

TEST(ReportHtml, FormatsNumbers) {
  EXPECT_EQ(formatNumber(42.0), "42");
  EXPECT_EQ(formatNumber(0.91234), "0.9123");
  EXPECT_EQ(formatNumber(812.5), "812.5");
  EXPECT_EQ(formatNumber(12345.678), "1.235e+04");
}

TEST(ReportHtml, RowsOfThePresentKeys) {
  const auto rows = summaryRows(nlohmann::json::parse(kSummary));
  std::map<std::string, std::string> byLabel(rows.begin(), rows.end());
  EXPECT_EQ(byLabel["surfaces (rectangles)"], "42");
  EXPECT_EQ(byLabel["explained fraction"], "0.9123");
  EXPECT_EQ(byLabel["termination"], "converged");
  EXPECT_EQ(byLabel["EM update per scan, p99"], "20.25 ms");
  EXPECT_EQ(byLabel["realtime factor"], "4.125");
  EXPECT_EQ(byLabel.count("EM update per scan, max"), 0u);  // null
  EXPECT_EQ(byLabel.count("raw triangles"), 0u);            // absent
  EXPECT_TRUE(summaryRows(nlohmann::json()).empty());
}

TEST(ReportHtml, PageHasImagesWarningsAndEscapedText) {
  const std::string html = reportHtml(nlohmann::json::parse(kSummary),
                                      {{"map_top.png", "top <view>"}}, {"no EGL & no GL"});
  EXPECT_NE(html.find("<img src=\"map_top.png\""), std::string::npos);
  EXPECT_NE(html.find("top &lt;view&gt;"), std::string::npos);
  EXPECT_NE(html.find("warning: no EGL &amp; no GL"), std::string::npos);
  EXPECT_NE(html.find(">42<"), std::string::npos);
  EXPECT_EQ(html.find("http"), std::string::npos);  // self-contained
  EXPECT_EQ(html.find("<script"), std::string::npos);
}

}  // namespace
}  // namespace pmap::report
