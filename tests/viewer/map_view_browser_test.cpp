// Issue 13, item 10: what viewer.html lets a user see of a map, checked in
// headless Chromium (tools/viewer/probe.js) on a two-room flat written by the
// real exporter (test_flat.h): every surface shows from the default view
// (double-sided, the robot's unseen side see-through), the robot path is
// drawn, a click on a surface shows its id, size, normal and support, the
// ceilings toggle hides the ceilings, "frame all" fits the whole map.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "browser_check.h"
#include "pmap/products/map_gltf.h"
#include "pmap/viewer/viewer_html.h"
#include "test_flat.h"

namespace pmap::viewer {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;
using namespace testing;  // NOLINT: the flat's surface ids

const test::BrowserTools kTools{PMAP_NODE_EXECUTABLE, PMAP_CHROMIUM_EXECUTABLE,
                                PMAP_VIEWER_TOOLS_DIR};

/// A surface "shows" with at least this many pixels in the half-size render.
constexpr int kMinPixels = 20;

class MapView : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string missing = test::missingBrowserTools(kTools);
    if (!missing.empty()) {
      GTEST_FAIL() << missing;
    }
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::path(PMAP_TEST_TMP_DIR) / "viewer_map_view" / info->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    writeViewerHtml(dir_ / "viewer.html", products::encodeMapGlb(flatModel(), false), {},
                    {{"title", "flat"}, {"surfaces", int(kFlatSurfaces)}});
  }

  /// The probe's steps (after the initial state), or an empty array on failure.
  json probe(const std::vector<std::string>& steps) {
    std::string log;
    const fs::path report = dir_ / "report.json";
    const int status = test::runProbe(kTools, dir_ / "viewer.html", report, steps, log);
    std::cout << log;
    if (status != 0) {
      ADD_FAILURE() << "probe.js failed: " << log;
      return json::array();
    }
    const json r = json::parse(test::readAll(report));
    EXPECT_TRUE(r["pageErrors"].empty()) << r["pageErrors"].dump();
    EXPECT_TRUE(r["consoleErrors"].empty()) << r["consoleErrors"].dump();
    EXPECT_TRUE(r["externalRequests"].empty()) << r["externalRequests"].dump();
    return r["steps"];
  }

  fs::path dir_;
};

/// Pixels of each surface id in a "pixels" step.
std::map<int, int> pixelsById(const json& step) {
  std::map<int, int> pixels;
  for (const json& s : step["pixels"]["surfaces"]) {
    pixels[s["id"].get<int>()] = s["pixels"].get<int>();
  }
  return pixels;
}

int surfacesShown(const std::map<int, int>& pixels) {
  int shown = 0;
  for (const auto& [id, n] : pixels) {
    shown += n >= kMinPixels ? 1 : 0;
  }
  return shown;
}

TEST_F(MapView, Item10_AllSurfacesVisibleFromDefaultView) {
  const json steps = probe({"pixels", "toggle:pmap-see-through-toggle", "pixels"});
  ASSERT_EQ(steps.size(), 3u);
  const auto pixels = pixelsById(steps[0]);
  ASSERT_EQ(pixels.size(), std::size_t(kFlatSurfaces));
  for (const auto& [id, n] : pixels) {
    EXPECT_GE(n, kMinPixels) << "surface " << id << " does not show from the default view";
  }
  EXPECT_TRUE(steps[0]["state"]["boxInView"].get<bool>());
  // The control: both sides solid, the ceiling hides the rooms from above.
  EXPECT_FALSE(steps[2]["state"]["seeThrough"].get<bool>());
  const auto solid = pixelsById(steps[2]);
  EXPECT_LT(solid.at(kFloor), kMinPixels);
  EXPECT_LT(surfacesShown(solid), int(kFlatSurfaces));
  std::cout << "surfaces shown: " << surfacesShown(pixels) << " see-through, "
            << surfacesShown(solid) << " solid\n";
}

TEST_F(MapView, Item10_RobotPathIsDrawn) {
  const json steps = probe({"pixels", "toggle:pmap-path-toggle", "pixels"});
  ASSERT_EQ(steps.size(), 3u);
  const json& path = steps[0]["state"]["path"];
  ASSERT_TRUE(path.is_object()) << "no robot path in the page";
  EXPECT_TRUE(path["visible"].get<bool>());
  EXPECT_EQ(path["positions"], 4);
  EXPECT_NEAR(path["length_m"].get<double>(), flatPathLength(), 1e-3);
  EXPECT_GT(steps[0]["pixels"]["pathPixels"].get<int>(), 50);
  EXPECT_FALSE(steps[2]["state"]["path"]["visible"].get<bool>());
  EXPECT_EQ(steps[2]["pixels"]["pathPixels"], 0);
}

TEST_F(MapView, Item10_ClickingASurfaceShowsItsInfo) {
  const json steps = probe({"click-surface:" + std::to_string(kFloor),
                            "click-surface:" + std::to_string(kNorthWall), "click:1270,790"});
  ASSERT_EQ(steps.size(), 3u);
  const json& floor = steps[0]["state"]["selected"];
  ASSERT_TRUE(floor.is_object()) << "the click selected nothing";
  EXPECT_EQ(floor["id"], kFloor);
  EXPECT_EQ(floor["kind"], "floor");
  EXPECT_NEAR(floor["width_m"].get<double>(), 8.0, 1e-3);
  EXPECT_NEAR(floor["height_m"].get<double>(), 5.0, 1e-3);
  EXPECT_NEAR(floor["area_m2"].get<double>(), 40.0, 1e-3);
  EXPECT_EQ(floor["normal"], json({0, 0, 1}));
  EXPECT_EQ(floor["support"], flatSupport(kFloor));
  const std::string panel = steps[0]["panel"];
  for (const char* text : {"surface 0 (floor)", "size: 8.00 m × 5.00 m", "area: 40.00 m²",
                           "normal: (0.00, 0.00, 1.00)", "support: 1,000 points"}) {
    EXPECT_NE(panel.find(text), std::string::npos) << "\"" << text << "\" not in: " << panel;
  }

  const json& wall = steps[1]["state"]["selected"];  // two tiles, one surface
  EXPECT_EQ(wall["id"], kNorthWall);
  EXPECT_EQ(wall["kind"], "wall");
  EXPECT_EQ(wall["tiles"], 2);
  EXPECT_NEAR(wall["width_m"].get<double>(), 8.0, 1e-3);
  EXPECT_NEAR(wall["height_m"].get<double>(), 2.5, 1e-3);
  EXPECT_EQ(wall["normal"], json({0, -1, 0}));  // towards the rooms
  EXPECT_EQ(wall["support"], flatSupport(kNorthWall));
  EXPECT_NE(steps[1]["panel"].get<std::string>().find("tiles: 2"), std::string::npos);

  EXPECT_TRUE(steps[2]["state"]["selected"].is_null()) << "a click on nothing keeps a selection";
  EXPECT_EQ(steps[2]["panel"], "");
}

// Where the see-through ceiling is in front of solid surfaces, the first click
// picks the solid one behind it, clicking again the next, then the ceiling.
TEST_F(MapView, Item10_ClickingAgainPicksTheSurfaceBehind) {
  const json steps = probe(
      {"click-surface:" + std::to_string(kCeiling), "click-again", "click-again", "click-again"});
  ASSERT_EQ(steps.size(), 4u);
  std::vector<int> picked;
  for (const json& step : steps) {
    ASSERT_TRUE(step["state"]["selected"].is_object()) << step.dump();
    picked.push_back(step["state"]["selected"]["id"].get<int>());
  }
  EXPECT_NE(picked[0], kCeiling) << "a see-through surface was picked before a solid one";
  EXPECT_NE(std::find(picked.begin(), picked.end(), kCeiling), picked.end())
      << "clicking again never reached the ceiling";
  for (std::size_t i = 1; i < picked.size(); ++i) {
    EXPECT_NE(picked[i], picked[i - 1]) << "click " << i << " picked the same surface again";
  }
  const auto ceiling = std::find(picked.begin(), picked.end(), kCeiling) - picked.begin();
  EXPECT_EQ(steps[ceiling]["state"]["selected"]["normal"], json({0, 0, -1}));
  EXPECT_NE(steps[ceiling]["panel"].get<std::string>().find("surface 1 (ceiling)"),
            std::string::npos);
}

TEST_F(MapView, Item10_CeilingToggleHidesCeilings) {
  const json steps = probe(
      {"pixels", "toggle:pmap-ceilings-toggle", "pixels", "toggle:pmap-ceilings-toggle", "pixels"});
  ASSERT_EQ(steps.size(), 5u);
  EXPECT_TRUE(steps[0]["state"]["ceilingsVisible"].get<bool>());
  EXPECT_GE(pixelsById(steps[0]).at(kCeiling), kMinPixels);
  EXPECT_FALSE(steps[1]["checked"].get<bool>());
  EXPECT_FALSE(steps[2]["state"]["ceilingsVisible"].get<bool>());
  const auto hidden = pixelsById(steps[2]);
  EXPECT_EQ(hidden.at(kCeiling), 0);
  EXPECT_EQ(surfacesShown(hidden), int(kFlatSurfaces) - 1);
  EXPECT_EQ(steps[2]["state"]["triangles"].get<int>(),
            steps[0]["state"]["triangles"].get<int>() - 2);  // the ceiling's two triangles
  EXPECT_GE(pixelsById(steps[4]).at(kCeiling), kMinPixels);
}

TEST_F(MapView, Item10_FrameAllFitsTheWholeMap) {
  const json steps = probe({"state", "zoom-in:12", "frame-all"});
  ASSERT_EQ(steps.size(), 3u);
  EXPECT_TRUE(steps[0]["state"]["boxInView"].get<bool>()) << "the default view crops the map";
  EXPECT_FALSE(steps[1]["state"]["boxInView"].get<bool>()) << "zooming in did not crop the map";
  const json& framed = steps[2]["state"];
  EXPECT_TRUE(framed["boxInView"].get<bool>()) << framed.dump();
  EXPECT_NE(framed["camera"], steps[1]["state"]["camera"]);
  // The target is the map's centre and the direction of view is kept.
  const auto vec = [](const json& v) {
    return Eigen::Vector3d(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
  };
  const json& box = framed["box"];
  EXPECT_TRUE(
      vec(framed["camera"]["target"]).isApprox((vec(box["min"]) + vec(box["max"])) / 2, 1e-3));
  const auto direction = [&](const json& camera) {
    return (vec(camera["position"]) - vec(camera["target"])).normalized();
  };
  EXPECT_GT(direction(framed["camera"]).dot(direction(steps[1]["state"]["camera"])), 0.999);
}

}  // namespace
}  // namespace pmap::viewer
