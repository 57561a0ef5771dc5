// map.glb checked by the Khronos glTF validator (npm gltf-validator, run with
// node through tools/web/validate-gltf.js): a real parser, not our reader.
#include <sys/wait.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iostream>

#include "glb_reader.h"
#include "gltf_validate.h"
#include "map_model_fixture.h"
#include "pmap/products/glb_container.h"
#include "pmap/products/map_gltf.h"

namespace pmap::products {
namespace {
namespace fs = std::filesystem;

using pmap::test::Validation;

std::string missingTools() {
  return pmap::test::missingValidator(PMAP_NODE, PMAP_WEB_TOOLS_DIR);
}

Validation validate(const fs::path& glb) {
  return pmap::test::validateGltf(PMAP_NODE, PMAP_WEB_TOOLS_DIR, glb);
}

class GltfValidator : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string missing = missingTools();
    if (!missing.empty()) {
      GTEST_FAIL() << missing;
    }
  }
};

void expectValid(const Validation& v) {
  ASSERT_TRUE(v.report.is_object()) << "validator output is not JSON: " << v.output;
  EXPECT_EQ(v.report["numErrors"], 0) << v.output;
  EXPECT_EQ(v.report["numWarnings"], 0) << v.output;
  EXPECT_EQ(v.exit_code, 0) << v.output;
}

TEST_F(GltfValidator, TexturedMapIsValid) {
  const fs::path dir = test::freshDir("gltf_validator_textured");
  writeMapGlb(dir / "map.glb", test::texturedRoomModel(), /*with_textures=*/true);
  expectValid(validate(dir / "map.glb"));
}

TEST_F(GltfValidator, GeometryOnlyMapIsValid) {
  const fs::path dir = test::freshDir("gltf_validator_geometry");
  writeMapGeometryGlb(dir / "map.glb", test::texturedRoomModel());
  expectValid(validate(dir / "map.glb"));
}

TEST_F(GltfValidator, UncolouredFineOnlyAndEmptyMapsAreValid) {
  const fs::path dir = test::freshDir("gltf_validator_plain");
  MapModel m = test::texturedRoomModel();
  m.fine.colors.clear();
  writeMapGlb(dir / "uncoloured.glb", m, true);
  expectValid(validate(dir / "uncoloured.glb"));
  m.quads.clear();
  writeMapGlb(dir / "fine_only.glb", m, true);
  expectValid(validate(dir / "fine_only.glb"));
  writeMapGlb(dir / "empty.glb", MapModel{}, true);
  const Validation empty = validate(dir / "empty.glb");
  EXPECT_EQ(empty.report["numErrors"], 0) << empty.output;
  EXPECT_EQ(empty.exit_code, 0) << empty.output;
}

// The validator really reads our data: a wrong POSITION max is an error.
TEST_F(GltfValidator, ReportsABrokenFile) {
  auto parts = test::parseGlb(encodeMapGlb(test::texturedRoomModel(), true));
  const int position = parts.json["meshes"][0]["primitives"][0]["attributes"]["POSITION"];
  parts.json["accessors"][position]["max"] = {100.0, 100.0, 100.0};
  const fs::path dir = test::freshDir("gltf_validator_broken");
  const auto broken = packGlb(parts.json.dump(), parts.bin);
  std::ofstream(dir / "broken.glb", std::ios::binary)
      .write(reinterpret_cast<const char*>(broken.data()),
             static_cast<std::streamsize>(broken.size()));
  const Validation v = validate(dir / "broken.glb");
  ASSERT_TRUE(v.report.is_object()) << v.output;
  EXPECT_GT(v.report["numErrors"].get<int>(), 0) << v.output;
  EXPECT_EQ(v.exit_code, 1) << v.output;
}

}  // namespace
}  // namespace pmap::products
