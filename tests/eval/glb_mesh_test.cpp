// The glTF reader of map-eval against the project's glTF writer: the
// triangles come back in world coordinates; malformed files are InputErrors.
#include "pmap/eval/glb_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <limits>

#include "nan_glb.h"
#include "pmap/common/error.h"
#include "pmap/products/map_gltf.h"

namespace pmap::eval {
namespace {
namespace fs = std::filesystem;
using Eigen::Vector3d;

fs::path tmpDir() {
  const fs::path dir = fs::path(PMAP_TEST_TMP_DIR) / "glb_mesh";
  fs::create_directories(dir);
  return dir;
}

TEST(GlbMesh, ReadsRectanglesAndFineTrianglesInWorldCoordinates) {
  products::MapModel m;
  products::TexturedQuad q;
  q.surface_id = 4;
  q.corners = {Vector3d(0, 0, 0), Vector3d(2, 0, 0), Vector3d(2, 0, 3), Vector3d(0, 0, 3)};
  q.normal = Vector3d(0, -1, 0);
  m.quads.push_back(q);
  m.fine.vertices = {Vector3d(5, 5, 1), Vector3d(6, 5, 1), Vector3d(5, 6, 1.5)};
  m.fine.triangles = {{0, 1, 2}};
  const fs::path glb = tmpDir() / "map.glb";
  products::writeMapGlb(glb, m, false);
  const std::vector<Triangle3> t = readGlbTriangles(glb);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_TRUE(t[0].a.isApprox(Vector3d(0, 0, 0)));
  EXPECT_TRUE(t[0].b.isApprox(Vector3d(2, 0, 0)));
  EXPECT_TRUE(t[0].c.isApprox(Vector3d(2, 0, 3)));
  EXPECT_TRUE(t[1].c.isApprox(Vector3d(0, 0, 3)));
  EXPECT_TRUE(t[2].c.isApprox(Vector3d(5, 6, 1.5)));
}

TEST(GlbMesh, EmptyModelHasNoTriangles) {
  const fs::path glb = tmpDir() / "empty.glb";
  products::writeMapGlb(glb, products::MapModel{}, false);
  EXPECT_TRUE(readGlbTriangles(glb).empty());
}

TEST(GlbMesh, MalformedFilesAreInputErrors) {
  const fs::path bad = tmpDir() / "bad.glb";
  std::ofstream(bad) << "not a glb file at all";
  EXPECT_THROW(readGlbTriangles(bad), InputError);
  EXPECT_THROW(readGlbTriangles(tmpDir() / "missing.glb"), InputError);
  // A valid header and JSON chunk whose accessor points past the buffer.
  products::MapModel m;
  m.fine.vertices = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0)};
  m.fine.triangles = {{0, 1, 2}};
  std::vector<std::uint8_t> bytes = products::encodeMapGlb(m, false);
  bytes.resize(bytes.size() - 8);  // cut into the BIN chunk
  const fs::path cut = tmpDir() / "cut.glb";
  std::ofstream(cut, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
  EXPECT_THROW(readGlbTriangles(cut), InputError);
}

TEST(GlbMesh, Item12_NanPositionOrADirectoryIsAnInputError) {
  products::MapModel m;
  m.fine.vertices = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 123.25)};
  m.fine.triangles = {{0, 1, 2}};
  const fs::path glb = tmpDir() / "nan.glb";
  ASSERT_TRUE(pmap::testing::writeGlbWithNan(m, 123.25f, glb));
  try {
    readGlbTriangles(glb);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("nan.glb: accessor "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("POSITION 2 is not finite"), std::string::npos);
  }
  fs::create_directories(tmpDir() / "dir.glb");
  EXPECT_THROW(readGlbTriangles(tmpDir() / "dir.glb"), InputError);
}

}  // namespace
}  // namespace pmap::eval
