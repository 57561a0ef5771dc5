#include "pmap/viewer/viewer_html.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "pmap/common/error.h"
#include "pmap/viewer/base64.h"
#include "pmap/viewer/point_subsample.h"
#include "test_glb.h"

namespace pmap::viewer {
namespace {
namespace fs = std::filesystem;

/// The text of the data block <script id="ID" ...>TEXT</script>.
std::string block(const std::string& page, const std::string& id) {
  const std::size_t open = page.find("<script id=\"" + id + "\"");
  if (open == std::string::npos) {
    return "<missing " + id + ">";
  }
  const std::size_t start = page.find('>', open) + 1;
  return page.substr(start, page.find("</script>", start) - start);
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t pos = text.find(what); pos != std::string::npos;
       pos = text.find(what, pos + 1)) {
    ++n;
  }
  return n;
}

TEST(ViewerHtml, EmbedsModelPointsInfoAndScript) {
  const auto quads = testing::corridorQuads(2);
  const auto glb = testing::makeQuadsGlb(quads);
  const auto points = testing::pointsOnQuads(quads, 1000, 7);
  const nlohmann::json info = {{"title", "Lab <3>"}, {"surfaces", 6}};
  const std::string page = renderViewerHtml(glb, points, info);

  EXPECT_NE(page.find("<title>Lab &lt;3&gt;</title>"), std::string::npos);
  const auto meta = nlohmann::json::parse(block(page, "pmap-meta"));
  EXPECT_EQ(meta["info"], info);
  EXPECT_EQ(meta["points"]["total"], 1000);
  EXPECT_EQ(meta["points"]["shown"], 1000);
  EXPECT_EQ(block(page, "pmap-glb"), encodeBase64(glb.data(), glb.size()));
  const auto packed = packFloat32(points);
  EXPECT_EQ(block(page, "pmap-points"), encodeBase64(packed.data(), packed.size()));
  EXPECT_NE(page.find("pmapViewer"), std::string::npos) << "the viewer bundle is missing";
  EXPECT_NE(page.find("Three.js Authors"), std::string::npos) << "three.js's licence notice";
  EXPECT_EQ(count(page, "</script>"), 4u) << "meta, glb, points and the viewer script";
  EXPECT_EQ(page.find("type=\"module\""), std::string::npos);
}

TEST(ViewerHtml, SubsamplesManyPoints) {
  std::vector<Eigen::Vector3f> points(kMaxViewerPoints + 10, Eigen::Vector3f(1, 2, 3));
  points[0].x() = std::numeric_limits<float>::quiet_NaN();
  const auto meta = nlohmann::json::parse(block(renderViewerHtml({}, points, {}), "pmap-meta"));
  EXPECT_EQ(meta["points"]["total"], kMaxViewerPoints + 10);
  EXPECT_EQ(meta["points"]["shown"], subsamplePoints(points, kMaxViewerPoints).size());
  EXPECT_LE(meta["points"]["shown"].get<std::size_t>(), kMaxViewerPoints);
}

TEST(ViewerHtml, EmptyMapStillMakesAPage) {
  const std::string page = renderViewerHtml({}, {}, nlohmann::json());
  EXPECT_NE(page.find("<title>planar map</title>"), std::string::npos);
  EXPECT_EQ(block(page, "pmap-glb"), "");
  EXPECT_EQ(block(page, "pmap-points"), "");
  EXPECT_EQ(nlohmann::json::parse(block(page, "pmap-meta"))["info"], nlohmann::json::object());
}

TEST(ViewerHtml, InfoCannotBreakOutOfItsScript) {
  const nlohmann::json info = {{"title", "</script><script>alert(1)</script>"}};
  const std::string page = renderViewerHtml({}, {}, info);
  EXPECT_EQ(count(page, "</script>"), 4u);
  EXPECT_EQ(nlohmann::json::parse(block(page, "pmap-meta"))["info"], info);
}

TEST(ViewerHtml, RejectsANonGlbModelAndNonObjectInfo) {
  EXPECT_THROW(renderViewerHtml(std::vector<std::uint8_t>(40, 'x'), {}, {}), ProcessingError);
  EXPECT_THROW(renderViewerHtml({'g', 'l', 'T', 'F'}, {}, {}), ProcessingError);
  EXPECT_THROW(renderViewerHtml({}, {}, nlohmann::json::array({1, 2})), ProcessingError);
}

TEST(ViewerHtml, WritesTheFileAtomically) {
  const fs::path dir = fs::path(PMAP_TEST_TMP_DIR) / "viewer_html_write";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto glb = testing::makeQuadsGlb(testing::corridorQuads(1));
  writeViewerHtml(dir / "viewer.html", glb, {}, {{"surfaces", 3}});
  std::ifstream in(dir / "viewer.html", std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), renderViewerHtml(glb, {}, {{"surfaces", 3}}));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(ViewerHtml, UnwritableTargetIsAnOutputError) {
  const fs::path missing = fs::path(PMAP_TEST_TMP_DIR) / "viewer_no_such_dir" / "x" / "v.html";
  fs::remove_all(missing.parent_path().parent_path());
  EXPECT_THROW(writeViewerHtml(missing, {}, {}, {}), OutputError);
}

}  // namespace
}  // namespace pmap::viewer
