// planar-mapper's map products on the bundled sample (a 30 s drive with
// cameras): every file is written, textured, and read back by real parsers
// where we have them (Coin3D for map.wrl, MRPT for map.3Dscene; the glTF
// validator and the browser run as their own CTest tests).
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "app_runner.h"
#include "browser_check.h"
#include "coin_reader.h"
#include "gltf_validate.h"
#include "pmap/mapper/planar_mapper_app.h"
#include "pmap/scene/map_scene.h"
#include "pmap/scene/scene_file.h"
#include "rawlog_fixtures.h"

namespace pmap::mapper {
namespace {
namespace fs = std::filesystem;

const fs::path kSample = fs::path(PMAP_SOURCE_DIR) / "share/sample/default-L.rawlog";

int run(const std::vector<std::string>& args) {
  return testing::runMain(&planarMapperMain, "planar-mapper", args);
}

nlohmann::json readJson(const fs::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

class SampleProducts : public ::testing::Test {
 protected:
  // planar-mapper ran once on the sample (CTest fixture sample_products).
  static void SetUpTestSuite() {
    out_ = PMAP_SAMPLE_OUT;
    summary_ = readJson(out_ / "summary.json");
  }
  static fs::path out_;
  static nlohmann::json summary_;
};
fs::path SampleProducts::out_;
nlohmann::json SampleProducts::summary_;

TEST_F(SampleProducts, WritesEveryMapProduct) {
  for (const char* f :
       {"map.wrl", "map.glb", "map.3Dscene", "viewer.html", "textures.csv", "surfaces.csv",
        "points.ply", "report/report.html", "report/map_perspective.png", "report/map_top.png",
        "report/em_per_scan.png"}) {
    EXPECT_TRUE(fs::exists(out_ / f)) << f;
  }
  const auto& t = summary_["texture"];
  ASSERT_TRUE(t["textured"].get<bool>()) << t.dump();
  EXPECT_GT(t["frames_used"].get<int>(), 20);
  EXPECT_GT(t["textured_tiles"].get<int>(), 3);
  EXPECT_GT(t["coverage"].get<double>(), 0.3);
  EXPECT_NEAR(t["pixels_per_m"].get<double>(), 200.0, 1.0);
  EXPECT_TRUE(summary_["report_warnings"].empty()) << summary_["report_warnings"].dump();
}

TEST_F(SampleProducts, TexturesCsvNamesThePngsWithTheirSizes) {
  std::ifstream csv(out_ / "textures.csv");
  std::string line;
  std::getline(csv, line);
  int rows = 0;
  while (std::getline(csv, line)) {
    const std::string file = line.substr(0, line.find(','));
    const cv::Mat img = cv::imread((out_ / file).string());
    ASSERT_FALSE(img.empty()) << file;
    std::stringstream fields(line);
    std::string f, id, tile, w, h;
    std::getline(fields, f, ','), std::getline(fields, id, ','), std::getline(fields, tile, ',');
    std::getline(fields, w, ','), std::getline(fields, h, ',');
    EXPECT_EQ(img.cols, std::stoi(w));
    EXPECT_EQ(img.rows, std::stoi(h));
    EXPECT_LE(std::max(img.cols, img.rows), 2048);
    ++rows;
  }
  EXPECT_EQ(rows, summary_["texture"]["textured_tiles"].get<int>());
}

TEST_F(SampleProducts, CoinReadsTheVrmlWithOneShapePerQuadPlusFineTriangles) {
  SoSeparator* root = pmap::test::readScene(out_ / "map.wrl");
  ASSERT_NE(root, nullptr);
  EXPECT_TRUE(pmap::test::coinReadErrors().empty()) << pmap::test::coinReadErrors().front();
  const auto shapes = pmap::test::shapesOf(root);
  const int fine = summary_["fine_triangles"].get<int>() > 0 ? 1 : 0;
  EXPECT_EQ(static_cast<int>(shapes.size()), summary_["texture"]["tiles"].get<int>() + fine);
  EXPECT_EQ(static_cast<int>(pmap::test::imageTexturesOf(shapes).size()),
            summary_["texture"]["textured_tiles"].get<int>());
  root->unref();
}

TEST_F(SampleProducts, SceneLoadsBackInMrptWithEveryObject) {
  const auto scene = scene::readMapScene(out_ / "map.3Dscene");
  // One object per textured quad, the fine triangles, the path and the grid.
  EXPECT_EQ(scene::countSceneObjects(*scene),
            static_cast<std::size_t>(summary_["texture"]["tiles"].get<int>()) + 3);
}

TEST_F(SampleProducts, ViewerEmbedsTheModel) {
  std::ifstream in(out_ / "viewer.html");
  const std::string page((std::istreambuf_iterator<char>(in)), {});
  EXPECT_GT(page.size(), fs::file_size(out_ / "map.glb"));  // base64 of the GLB at least
  EXPECT_EQ(page.find("<script src="), std::string::npos);  // nothing loaded from elsewhere
}

TEST_F(SampleProducts, GltfValidatorFindsNoErrorInMapGlb) {
  const std::string missing = pmap::test::missingValidator(PMAP_NODE, PMAP_WEB_TOOLS_DIR);
  ASSERT_TRUE(missing.empty()) << missing;
  const auto v = pmap::test::validateGltf(PMAP_NODE, PMAP_WEB_TOOLS_DIR, out_ / "map.glb");
  ASSERT_TRUE(v.report.is_object()) << v.output;
  EXPECT_EQ(v.report["numErrors"], 0) << v.output;
  EXPECT_EQ(v.exit_code, 0) << v.output;
}

// The geometry-only files the baselines compare (doc/outputs.md): valid
// glTF, smaller than the textured map.
TEST_F(SampleProducts, GeometryOnlyGlbFilesAreValid) {
  const std::string missing = pmap::test::missingValidator(PMAP_NODE, PMAP_WEB_TOOLS_DIR);
  ASSERT_TRUE(missing.empty()) << missing;
  for (const char* f : {"map-geometry.glb", "raw.glb"}) {
    ASSERT_TRUE(fs::exists(out_ / f)) << f;
    const auto v = pmap::test::validateGltf(PMAP_NODE, PMAP_WEB_TOOLS_DIR, out_ / f);
    ASSERT_TRUE(v.report.is_object()) << v.output;
    EXPECT_EQ(v.report["numErrors"], 0) << f << ": " << v.output;
  }
  EXPECT_LT(fs::file_size(out_ / "map-geometry.glb"), fs::file_size(out_ / "map.glb"));
}

TEST_F(SampleProducts, ViewerDrawsTheTexturedMapInHeadlessChromium) {
  const pmap::test::BrowserTools tools{PMAP_NODE, PMAP_CHROMIUM_EXECUTABLE, PMAP_VIEWER_TOOLS_DIR};
  const std::string missing = pmap::test::missingBrowserTools(tools);
  ASSERT_TRUE(missing.empty()) << missing;
  std::string log;
  const fs::path png = out_ / "viewer.png", report_file = out_ / "viewer-report.json";
  ASSERT_EQ(pmap::test::runScreenshot(tools, out_ / "viewer.html", png, report_file, log), 0)
      << log;
  const auto report = nlohmann::json::parse(pmap::test::readAll(report_file));
  const auto& first = report["initial"];
  EXPECT_TRUE(first["ready"].get<bool>());
  // Every triangle of the model drawn: 2 per textured quad + the fine ones.
  EXPECT_EQ(first["triangles"].get<int>(), first["modelTriangles"].get<int>());
  EXPECT_EQ(first["modelTriangles"].get<int>(),
            2 * summary_["texture"]["tiles"].get<int>() + summary_["fine_triangles"].get<int>());
  EXPECT_TRUE(report["externalRequests"].empty()) << report["externalRequests"].dump();
  EXPECT_GT(pmap::test::canvasStddev(png, report), pmap::test::kMinCanvasStddev);
}

TEST(MapProducts, NoTexturesWritesGeometryOnly) {
  const fs::path out = testing::freshTestDir("map_products_untextured") / "out";
  ASSERT_EQ(run({"--rawlog", kSample.string(), "--out", out.string(), "--no-textures", "-q",
                 "--to-index", "200"}),
            0);
  const auto s = readJson(out / "summary.json");
  EXPECT_FALSE(s["texture"]["textured"].get<bool>());
  EXPECT_EQ(s["texture"]["reason"], "--no-textures");
  EXPECT_FALSE(fs::exists(out / "textures.csv"));
  EXPECT_FALSE(fs::exists(out / "textures"));
  EXPECT_TRUE(fs::exists(out / "map.glb"));
}

TEST(MapProducts, MissingCameraImagesAreAnInputErrorNamingTheFile) {
  const fs::path dir = testing::freshTestDir("map_products_no_images");
  fs::copy_file(kSample, dir / "alone.rawlog");  // without its _Images folder
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(run({"--rawlog", (dir / "alone.rawlog").string(), "--out", (dir / "out").string(), "-q",
                 "--to-index", "100"}),
            2);
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find("CAMERA_"), std::string::npos) << err;
  EXPECT_NE(err.find("cannot be read"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(dir / "out/map.glb"));  // no partial map
  EXPECT_EQ(run({"--rawlog", (dir / "alone.rawlog").string(), "--out", (dir / "out").string(), "-q",
                 "--to-index", "100", "--no-textures"}),
            0);
}

TEST(MapProducts, GuiWithoutADisplayIsAUsageError) {
  const char* display = std::getenv("DISPLAY");
  const std::string saved = display != nullptr ? display : "";
  ::unsetenv("DISPLAY");
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(run({"--rawlog", kSample.string(), "--out",
                 (testing::freshTestDir("map_products_gui") / "out").string(), "--gui", "-q"}),
            1);
  EXPECT_NE(::testing::internal::GetCapturedStderr().find("xvfb-run"), std::string::npos);
  if (!saved.empty()) {
    ::setenv("DISPLAY", saved.c_str(), 1);
  }
}

}  // namespace
}  // namespace pmap::mapper
