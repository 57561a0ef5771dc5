#include "pmap/products/map_vrml.h"

#include <unistd.h>

#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <regex>
#include <sstream>

#include "map_model_fixture.h"
#include "pmap/common/error.h"

namespace pmap::products {
namespace {
namespace fs = std::filesystem;

std::string readText(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
    ++n;
  }
  return n;
}

std::vector<std::string> urls(const std::string& text) {
  std::vector<std::string> out;
  const std::regex url("ImageTexture \\{ url \"([^\"]+)\"");
  for (std::sregex_iterator it(text.begin(), text.end(), url), end; it != end; ++it) {
    out.push_back((*it)[1]);
  }
  return out;
}

TEST(MapVrml, OneShapePerQuadAndOneForTheFineTriangles) {
  const fs::path dir = test::freshDir("map_vrml_shapes");
  const MapModel m = test::texturedRoomModel();
  writeMapVrml(dir / "map.wrl", m, "test room");
  const std::string text = readText(dir / "map.wrl");
  EXPECT_EQ(text.rfind("#VRML V2.0 utf8\n# test room\n", 0), 0u);
  EXPECT_EQ(count(text, "Shape {"), m.quads.size() + 1);
  EXPECT_EQ(count(text, "IndexedFaceSet {"), m.quads.size() + 1);
  EXPECT_EQ(count(text, "solid FALSE"), m.quads.size() + 1);
  EXPECT_EQ(count(text, "coordIndex [ 0 1 2 -1, 0 2 3 -1 ]"), m.quads.size());
  EXPECT_EQ(count(text, "TextureCoordinate { point [ 0 0, 1 0, 1 1, 0 1, ] }"), m.quads.size());
  EXPECT_EQ(count(text, "DEF surface_12_0 Shape"), 1u);
  EXPECT_EQ(count(text, "DEF fine_triangles Shape"), 1u);
}

TEST(MapVrml, OneImageTexturePerTexturedQuadWithItsPng) {
  const fs::path dir = test::freshDir("map_vrml_textures");
  const MapModel m = test::texturedRoomModel();
  writeMapVrml(dir / "map.wrl", m);
  const std::vector<std::string> found = urls(readText(dir / "map.wrl"));
  EXPECT_EQ(found, (std::vector<std::string>{"textures/surface_3_0.png", "textures/surface_7_0.png",
                                             "textures/surface_7_1.png"}));
  ASSERT_EQ(found.size(), test::texturedQuadCount(m));
  for (std::size_t i = 0; i < found.size(); ++i) {
    const cv::Mat png = cv::imread((dir / found[i]).string(), cv::IMREAD_UNCHANGED);
    ASSERT_FALSE(png.empty()) << found[i];
    EXPECT_EQ(png.size(), m.quads[i].texture.size()) << found[i];
    EXPECT_EQ(cv::norm(png, m.quads[i].texture, cv::NORM_INF), 0.0) << found[i];
  }
  EXPECT_EQ(test::filesBelow(dir),
            (std::vector<std::string>{"map.wrl", "textures/surface_3_0.png",
                                      "textures/surface_7_0.png", "textures/surface_7_1.png"}));
}

TEST(MapVrml, UntexturedQuadGetsItsMaterialColour) {
  const fs::path dir = test::freshDir("map_vrml_material");
  writeMapVrml(dir / "map.wrl", test::texturedRoomModel());
  const std::string text = readText(dir / "map.wrl");
  const std::size_t ceiling = text.find("DEF surface_12_0 Shape");
  ASSERT_NE(ceiling, std::string::npos);
  const std::string shape = text.substr(ceiling, text.find("\n}\n", ceiling) - ceiling);
  EXPECT_NE(shape.find("material Material { diffuseColor 0.500 0.250 1.000 }"), std::string::npos);
  EXPECT_EQ(shape.find("ImageTexture"), std::string::npos);
}

TEST(MapVrml, FineTrianglesWithAndWithoutVertexColours) {
  const fs::path dir = test::freshDir("map_vrml_fine");
  MapModel m = test::texturedRoomModel();
  writeMapVrml(dir / "coloured.wrl", m);
  std::string text = readText(dir / "coloured.wrl");
  EXPECT_EQ(count(text, "colorPerVertex TRUE"), 1u);
  EXPECT_NE(text.find("color Color { color [\n      1.000 0.000 0.000,\n      0.000 1.000 0.000,"),
            std::string::npos);
  EXPECT_NE(text.find("      0 1 2 -1,\n      1 3 2 -1,\n"), std::string::npos);
  m.fine.colors.clear();
  writeMapVrml(dir / "plain.wrl", m);
  text = readText(dir / "plain.wrl");
  EXPECT_EQ(text.find("Color {"), std::string::npos);
  EXPECT_NE(text.find("diffuseColor 0.750 0.250 0.200"), std::string::npos);
}

TEST(MapVrml, EmptyModelHasNoShapesNorTextureFolder) {
  const fs::path dir = test::freshDir("map_vrml_empty");
  writeMapVrml(dir / "map.wrl", MapModel{}, "first line\nsecond line");
  EXPECT_EQ(readText(dir / "map.wrl"), "#VRML V2.0 utf8\n# first line\n# second line\n");
  EXPECT_EQ(test::filesBelow(dir), std::vector<std::string>{"map.wrl"});
}

TEST(MapVrml, RewritingLeavesNoTemporaryFiles) {
  const fs::path dir = test::freshDir("map_vrml_rewrite");
  writeMapVrml(dir / "map.wrl", test::texturedRoomModel());
  writeMapVrml(dir / "map.wrl", test::texturedRoomModel());
  EXPECT_EQ(test::filesBelow(dir).size(), 4u);
}

TEST(MapVrml, FailedWritesKeepThePreviousMap) {
  const fs::path dir = test::freshDir("map_vrml_fails");
  writeMapVrml(dir / "map.wrl", MapModel{}, "previous");
  const std::string previous = readText(dir / "map.wrl");
  {
    std::ofstream blocker(dir / "textures");  // a file where the folder should be
  }
  EXPECT_THROW(writeMapVrml(dir / "map.wrl", test::texturedRoomModel()), OutputError);
  EXPECT_EQ(readText(dir / "map.wrl"), previous);
  fs::remove(dir / "textures");
  fs::create_directory(dir / ("map.wrl.tmp-" + std::to_string(::getpid())));
  EXPECT_THROW(writeMapVrml(dir / "map.wrl", test::texturedRoomModel()), OutputError);
  EXPECT_EQ(readText(dir / "map.wrl"), previous);
}

TEST(MapVrml, InvalidModelWritesNothing) {
  const fs::path dir = test::freshDir("map_vrml_invalid");
  MapModel m = test::texturedRoomModel();
  m.fine.triangles.push_back({0, 1, 9});
  EXPECT_THROW(writeMapVrml(dir / "map.wrl", m), std::invalid_argument);
  EXPECT_TRUE(test::filesBelow(dir).empty());
}

}  // namespace
}  // namespace pmap::products
