#include "pmap/scene/scene_file.h"

#include <gtest/gtest.h>
#include <mrpt/opengl/CSetOfTexturedTriangles.h>

#include <filesystem>
#include <fstream>

#include "pmap/common/error.h"
#include "pmap/scene/map_scene.h"
#include "scene_test_model.h"

namespace pmap::scene {
namespace {
namespace fs = std::filesystem;

fs::path testDir(const std::string& name) {
  const fs::path dir = fs::path(PMAP_TEST_TMP_DIR) / ("scene_file_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(SceneFile, RoundTripKeepsObjectsAndTexture) {
  const fs::path dir = testDir("round_trip");
  const std::vector<Eigen::Vector3d> points(5, Eigen::Vector3d(1, 0, 1));
  SceneOptions o;
  o.points = &points;
  o.add_axes = true;
  const auto model = test::smallModel();
  const auto scene = buildMapScene(model, o);
  const fs::path file = dir / "map.3Dscene";
  writeMapScene(file, *scene);
  ASSERT_TRUE(fs::is_regular_file(file));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);

  const auto loaded = readMapScene(file);
  EXPECT_EQ(countSceneObjects(*loaded), expectedObjectCount(model, o));
  EXPECT_EQ(countSceneObjects(*loaded), countSceneObjects(*scene));
  const auto wall = loaded->getByClass<mrpt::opengl::CSetOfTexturedTriangles>();
  ASSERT_TRUE(wall);
  EXPECT_EQ(wall->getTextureImage().getWidth(), 32u);
  EXPECT_EQ(wall->getTextureImage().getHeight(), 16u);
  EXPECT_EQ(wall->getTrianglesCount(), 2u);
}

TEST(SceneFile, EmptyModelRoundTrips) {
  const fs::path file = testDir("empty") / "map.3Dscene";
  const SceneOptions o;
  writeMapScene(file, *buildMapScene(products::MapModel{}, o));
  EXPECT_EQ(countSceneObjects(*readMapScene(file)), 3u);
}

TEST(SceneFile, ReplacesAnExistingFile) {
  const fs::path file = testDir("replace") / "map.3Dscene";
  std::ofstream(file) << "old";
  writeMapScene(file, *buildMapScene(test::smallModel(), SceneOptions{}));
  EXPECT_GT(fs::file_size(file), 3u);
  EXPECT_NO_THROW(readMapScene(file));
}

TEST(SceneFile, MissingDirectoryIsAnOutputError) {
  const fs::path file = testDir("missing") / "no" / "map.3Dscene";
  try {
    writeMapScene(file, *buildMapScene(test::smallModel(), SceneOptions{}));
    FAIL() << "expected OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos);
  }
}

TEST(SceneFile, UnreadableFileIsAnInputError) {
  const fs::path dir = testDir("unreadable");
  std::ofstream(dir / "junk.3Dscene") << "not a scene";
  EXPECT_THROW(readMapScene(dir / "junk.3Dscene"), InputError);
  EXPECT_THROW(readMapScene(dir / "absent.3Dscene"), InputError);
}

}  // namespace
}  // namespace pmap::scene
