// viewer.html in a real browser: headless Chromium (WebGL through SwiftShader)
// opens the page from file:// with the network off, through
// tools/viewer/screenshot.js. The map must be DRAWN (triangles counted by
// three.js's renderer after the first frame), the raw-points toggle must draw
// the points, and the screenshot of the canvas must not be blank.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include <sys/wait.h>

#include "browser_check.h"
#include "pmap/viewer/viewer_html.h"
#include "test_glb.h"

namespace pmap::viewer {
namespace {
namespace fs = std::filesystem;

const test::BrowserTools kTools{PMAP_NODE_EXECUTABLE, PMAP_CHROMIUM_EXECUTABLE,
                                PMAP_VIEWER_TOOLS_DIR};
using test::kMinCanvasStddev;
using test::readAll;

class ViewerBrowser : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string missing = test::missingBrowserTools(kTools);
    if (!missing.empty()) {
      GTEST_FAIL() << missing;
    }
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::path(PMAP_TEST_TMP_DIR) / "viewer_browser" / test->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }

  /// Writes viewer.html, opens it in Chromium, ticks the points toggle;
  /// returns screenshot.js's report with the canvas's "stddev" added.
  nlohmann::json openInBrowser(const std::vector<std::uint8_t>& glb,
                               const std::vector<Eigen::Vector3f>& points,
                               const nlohmann::json& info) {
    writeViewerHtml(dir_ / "viewer.html", glb, points, info);
    std::string log;
    const fs::path png = dir_ / "viewer.png", report_file = dir_ / "report.json";
    const int status = test::runScreenshot(kTools, dir_ / "viewer.html", png, report_file, log);
    std::cout << log;
    if (status != 0) {
      ADD_FAILURE() << "screenshot.js failed: " << log;
      return nlohmann::json::object();
    }
    auto report = nlohmann::json::parse(readAll(report_file));
    report["stddev"] = test::canvasStddev(png, report);
    std::cout << "canvas grey stddev " << report["stddev"] << " in " << png.string() << "\n";
    return report;
  }

  fs::path dir_;
};

TEST_F(ViewerBrowser, DrawsTheCorridorOpenedFromDiskWithoutNetwork) {
  const auto quads = testing::corridorQuads(5);  // 15 quads, 30 triangles
  const auto points = testing::pointsOnQuads(quads, 40000, 11);
  const auto report = openInBrowser(testing::makeQuadsGlb(quads), points,
                                    {{"title", "corridor"}, {"surfaces", quads.size()}});
  ASSERT_TRUE(report.contains("initial"));

  const auto& initial = report["initial"];
  EXPECT_TRUE(initial["ready"].get<bool>());
  EXPECT_EQ(initial["modelTriangles"], 30);
  EXPECT_GT(initial["triangles"].get<int>(), 0) << "the map was loaded but not drawn";
  EXPECT_EQ(initial["pointsVisible"], false);
  EXPECT_EQ(initial["points"], 0);
  EXPECT_FALSE(report["toggleDisabled"].get<bool>());
  const auto& toggled = report["afterToggle"];
  EXPECT_EQ(toggled["pointsVisible"], true);
  EXPECT_EQ(toggled["points"], 40000) << "the raw points toggle drew no points";
  EXPECT_EQ(toggled["triangles"], initial["triangles"]);

  EXPECT_EQ(report["title"], "corridor");
  EXPECT_TRUE(report["externalRequests"].empty()) << report["externalRequests"].dump();
  EXPECT_TRUE(report["pageErrors"].empty()) << report["pageErrors"].dump();
  EXPECT_TRUE(report["consoleErrors"].empty()) << report["consoleErrors"].dump();
  EXPECT_GT(report["stddev"].get<double>(), kMinCanvasStddev) << "blank canvas";
}

// The control for the blank-canvas threshold: a page with nothing to draw
// (only the floor grid) stays under it.
TEST_F(ViewerBrowser, EmptyMapDrawsNoTrianglesAndLooksBlank) {
  const auto report = openInBrowser({}, {}, {{"title", "empty"}});
  ASSERT_TRUE(report.contains("initial"));
  EXPECT_TRUE(report["initial"]["ready"].get<bool>());
  EXPECT_EQ(report["initial"]["triangles"], 0);
  EXPECT_TRUE(report["toggleDisabled"].get<bool>()) << "a points toggle without points";
  EXPECT_EQ(report["afterToggle"]["points"], 0);
  EXPECT_LT(report["stddev"].get<double>(), kMinCanvasStddev);
}

// A model three.js cannot read is reported (HUD and window.pmapViewer.error),
// and screenshot.js fails naming it.
TEST_F(ViewerBrowser, BrokenModelIsReported) {
  std::vector<std::uint8_t> glb = testing::makeQuadsGlb(testing::corridorQuads(1));
  std::fill(glb.begin() + 20, glb.begin() + 40, std::uint8_t('#'));  // corrupt the JSON chunk
  writeViewerHtml(dir_ / "viewer.html", glb, {}, {});
  std::string log;
  EXPECT_EQ(test::runScreenshot(kTools, dir_ / "viewer.html", dir_ / "viewer.png",
                                dir_ / "report.json", log),
            1)
      << log;
  EXPECT_NE(log.find("the viewer failed"), std::string::npos) << log;
}

}  // namespace
}  // namespace pmap::viewer
