#include "pmap/report/report.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "pmap/common/error.h"
#include "report_test_model.h"

namespace pmap::report {
namespace {
namespace fs = std::filesystem;

fs::path testDir(const std::string& name) {
  const fs::path dir = fs::path(PMAP_TEST_TMP_DIR) / ("report_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string readText(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

nlohmann::json offlineSummary() {
  nlohmann::json s = {{"mode", "offline"},
                      {"surfaces", 4},
                      {"explained_fraction", 0.8765},
                      {"compression", 123.4},
                      {"iterations", 3},
                      {"termination", "converged"},
                      {"realtime_factor", 2.5},
                      {"timing_s", {{"total", 1.25}}}};
  for (int i = 1; i <= 3; ++i) {
    s["history"].push_back(
        {{"iteration", i}, {"surfaces", 6 - i}, {"explained_fraction", 0.5 + 0.1 * i}});
  }
  return s;
}

ReportOptions smallOptions() {
  ReportOptions o;
  o.views.width_px = 480;
  o.views.height_px = 320;
  o.chart_width_px = 640;
  o.chart_height_px = 480;
  return o;
}

TEST(Report, OfflineReportHasRendersChartAndPage) {
  const fs::path dir = testDir("offline");
  const auto model = test::corridor();
  const ReportResult r = writeReport(dir, {model, offlineSummary(), {}}, smallOptions());
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
  EXPECT_EQ(r.dir, dir / "report");
  for (const char* name : {"map_perspective.png", "map_top.png"}) {
    const cv::Mat img = cv::imread((r.dir / name).string());
    ASSERT_EQ(img.size(), cv::Size(480, 320)) << name;
    EXPECT_GT(test::greyStdDev(img), 10.0) << name;
    EXPECT_GT(test::countPixels(img, test::greenish), 200) << name;
  }
  const cv::Mat chart = cv::imread((r.dir / "em_iterations.png").string());
  EXPECT_EQ(chart.size(), cv::Size(640, 480));
  EXPECT_FALSE(fs::exists(r.dir / "em_per_scan.png"));
  const std::string html = readText(r.dir / "report.html");
  for (const char* name : {"map_perspective.png", "map_top.png", "em_iterations.png"}) {
    EXPECT_NE(html.find(std::string("src=\"") + name + "\""), std::string::npos) << name;
  }
  for (const char* number : {"0.8765", "123.4", "converged", "2.5", "1.25 s"}) {
    EXPECT_NE(html.find(number), std::string::npos) << number;
  }
  EXPECT_EQ(r.files.back(), "report.html");
  EXPECT_EQ(std::distance(fs::directory_iterator(r.dir), fs::directory_iterator()), 4);
}

TEST(Report, OnlineReportHasThePerScanChart) {
  const fs::path dir = testDir("online");
  std::vector<OnlineScanRow> rows;
  for (int i = 0; i < 50; ++i) {
    rows.push_back({i, 1.0 + i % 7, i / 5});
  }
  nlohmann::json summary = {{"mode", "online"},
                            {"em_per_scan_ms", {{"p50", 3.5}, {"p99", 7.25}, {"max", 7.5}}}};
  const auto model = test::corridor();
  const ReportResult r = writeReport(dir, {model, summary, rows}, smallOptions());
  EXPECT_EQ(cv::imread((r.dir / "em_per_scan.png").string()).size(), cv::Size(640, 480));
  EXPECT_FALSE(fs::exists(r.dir / "em_iterations.png"));
  const std::string html = readText(r.dir / "report.html");
  EXPECT_NE(html.find("src=\"em_per_scan.png\""), std::string::npos);
  EXPECT_NE(html.find("7.25 ms"), std::string::npos);
}

TEST(Report, EmptyMapStillGivesAValidReport) {
  const fs::path dir = testDir("empty");
  const products::MapModel empty;
  nlohmann::json summary = {
      {"mode", "offline"}, {"surfaces", 0}, {"history", nlohmann::json::array()}};
  const ReportResult r = writeReport(dir, {empty, summary, {}}, smallOptions());
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_EQ(cv::imread((r.dir / "map_top.png").string()).size(), cv::Size(480, 320));
  const std::string html = readText(r.dir / "report.html");
  EXPECT_NE(html.find("</html>"), std::string::npos);
  EXPECT_NE(html.find(">0<"), std::string::npos);
}

TEST(Report, WarningsInsteadOfPicturesAndStalePicturesRemoved) {
  const fs::path dir = testDir("warnings");
  const auto model = test::corridor();
  writeReport(dir, {model, offlineSummary(), {}}, smallOptions());
  ASSERT_TRUE(fs::exists(dir / "report" / "map_top.png"));
  ReportOptions o = smallOptions();
  o.render_map = false;
  nlohmann::json bad = {{"history", {{{"iteration", 1}}}}};
  const ReportResult r = writeReport(dir, {model, bad, {}}, o);
  ASSERT_EQ(r.warnings.size(), 2u);
  EXPECT_FALSE(fs::exists(r.dir / "map_top.png"));
  EXPECT_FALSE(fs::exists(r.dir / "em_iterations.png"));
  const std::string html = readText(r.dir / "report.html");
  EXPECT_NE(html.find("map pictures not rendered"), std::string::npos);
  EXPECT_NE(html.find("history[0]"), std::string::npos);
}

TEST(Report, UnwritableDirectoryIsAnOutputError) {
  const fs::path dir = testDir("unwritable");
  std::ofstream(dir / "report") << "a file where the directory should be";
  const auto model = test::corridor();
  EXPECT_THROW(writeReport(dir, {model, nlohmann::json::object(), {}}, smallOptions()),
               OutputError);
}

}  // namespace
}  // namespace pmap::report
