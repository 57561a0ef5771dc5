#include "pmap/products/map_gltf.h"

#include <unistd.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <fstream>
#include <map>
#include <opencv2/imgcodecs.hpp>

#include "glb_reader.h"
#include "map_model_fixture.h"
#include "pmap/common/error.h"

namespace pmap::products {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

std::vector<std::uint8_t> readBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

const json& meshNamed(const test::GlbParts& p, const std::string& name) {
  for (const json& m : p.json["meshes"]) {
    if (m["name"] == name) {
      return m;
    }
  }
  throw std::runtime_error("no mesh " + name);
}

TEST(MapGltf, ContainerAndBufferLayout) {
  const auto glb = encodeMapGlb(test::texturedRoomModel(), true);
  const auto p = test::parseGlb(glb);
  EXPECT_EQ(p.magic, 0x46546C67u);
  EXPECT_EQ(p.version, 2u);
  EXPECT_EQ(p.length, glb.size());
  EXPECT_EQ(p.json_chunk_type, 0x4E4F534Au);
  EXPECT_EQ(p.bin_chunk_type, 0x004E4942u);
  EXPECT_EQ(p.json_chunk_length % 4, 0u);
  EXPECT_EQ(p.bin_chunk_length % 4, 0u);
  EXPECT_EQ(20 + p.json_chunk_length + 8 + p.bin_chunk_length, glb.size());
  const std::size_t buffer_length = p.json["buffers"][0]["byteLength"];
  EXPECT_LE(buffer_length, p.bin.size());
  EXPECT_GT(buffer_length + 4, p.bin.size());
  for (const json& v : p.json["bufferViews"]) {
    EXPECT_EQ(v["byteOffset"].get<std::size_t>() % 4, 0u) << v;
    EXPECT_LE(v["byteOffset"].get<std::size_t>() + v["byteLength"].get<std::size_t>(),
              buffer_length);
  }
  std::map<int, int> accessors_of_view;
  for (std::size_t i = 0; i < p.json["accessors"].size(); ++i) {
    const json& a = p.json["accessors"][i];
    const json& v = p.json["bufferViews"][a["bufferView"].get<int>()];
    ++accessors_of_view[a["bufferView"].get<int>()];
    const std::size_t size = test::componentSize(a["componentType"]);
    EXPECT_EQ(a["byteOffset"].get<std::size_t>() % size, 0u) << a;
    EXPECT_EQ(test::accessorStart(p, static_cast<int>(i)) % size, 0u) << a;
    EXPECT_LE(a["byteOffset"].get<std::size_t>() +
                  a["count"].get<std::size_t>() * test::componentCount(a["type"]) * size,
              v["byteLength"].get<std::size_t>())
        << a;
  }
  for (const auto& [view, accessors] : accessors_of_view) {  // shared vertex data needs a stride
    const json& v = p.json["bufferViews"][view];
    if (v["target"] == 34962 && accessors > 1) {
      EXPECT_EQ(v["byteStride"], 12) << v;
    }
    if (!v.contains("target") || v["target"] == 34963) {  // images, indices
      EXPECT_FALSE(v.contains("byteStride")) << v;
    }
  }
}

TEST(MapGltf, QuadMeshesCountsBoundsAndTexCoords) {
  const MapModel m = test::texturedRoomModel();
  const auto p = test::parseGlb(encodeMapGlb(m, true));
  EXPECT_EQ(p.json["meshes"].size(), m.quads.size() + 2);  // + fine triangles, path
  for (const TexturedQuad& q : m.quads) {
    const std::string name =
        "surface_" + std::to_string(q.surface_id) + "_" + std::to_string(q.tile);
    const json& prim = meshNamed(p, name)["primitives"][0];
    EXPECT_EQ(prim["mode"], 4);
    const json& attr = prim["attributes"];
    const json& pos = p.json["accessors"][attr["POSITION"].get<int>()];
    EXPECT_EQ(pos["count"], 4);
    Eigen::Vector3f lo = q.corners[0].cast<float>(), hi = lo;
    for (const Eigen::Vector3d& c : q.corners) {
      lo = lo.cwiseMin(c.cast<float>());
      hi = hi.cwiseMax(c.cast<float>());
    }
    EXPECT_EQ(pos["min"], json({lo.x(), lo.y(), lo.z()}));
    EXPECT_EQ(pos["max"], json({hi.x(), hi.y(), hi.z()}));
    const std::vector<float> xyz = test::floatsOf(p, attr["POSITION"]);
    EXPECT_EQ(Eigen::Vector3f(xyz[6], xyz[7], xyz[8]), q.corners[2].cast<float>());
    const std::vector<float> n = test::floatsOf(p, attr["NORMAL"]);
    EXPECT_EQ(n.size(), 12u);
    EXPECT_TRUE(Eigen::Vector3f(n[9], n[10], n[11]).isApprox(q.normal.cast<float>()));
    EXPECT_EQ(test::uintsOf(p, prim["indices"]), (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
    EXPECT_EQ(attr.contains("TEXCOORD_0"), !q.texture.empty());
    if (!q.texture.empty()) {  // (s, 1 - t) of (0,0) (1,0) (1,1) (0,1)
      EXPECT_EQ(test::floatsOf(p, attr["TEXCOORD_0"]),
                (std::vector<float>{0, 1, 1, 1, 1, 0, 0, 0}));
    }
  }
}

TEST(MapGltf, EmbeddedPngTexturesAndColourMaterials) {
  const MapModel m = test::texturedRoomModel();
  const auto p = test::parseGlb(encodeMapGlb(m, true));
  ASSERT_EQ(p.json["images"].size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const json& image = p.json["images"][i];
    EXPECT_EQ(image["mimeType"], "image/png");
    const json& view = p.json["bufferViews"][image["bufferView"].get<int>()];
    const std::vector<std::uint8_t> png(
        p.bin.begin() + view["byteOffset"].get<long>(),
        p.bin.begin() + view["byteOffset"].get<long>() + view["byteLength"].get<long>());
    const cv::Mat decoded = cv::imdecode(png, cv::IMREAD_UNCHANGED);
    EXPECT_EQ(decoded.size(), m.quads[i].texture.size());
    EXPECT_EQ(cv::norm(decoded, m.quads[i].texture, cv::NORM_INF), 0.0);
  }
  const json& floor = meshNamed(p, "surface_3_0")["primitives"][0];
  const json& textured = p.json["materials"][floor["material"].get<int>()];
  EXPECT_FALSE(textured["doubleSided"].get<bool>());  // rectangles face the robot
  const int texture = textured["pbrMetallicRoughness"]["baseColorTexture"]["index"];
  EXPECT_EQ(p.json["textures"][texture]["source"], 0);
  const json& ceiling = meshNamed(p, "surface_12_0")["primitives"][0];
  const json& pbr = p.json["materials"][ceiling["material"].get<int>()]["pbrMetallicRoughness"];
  // sRGB (0.5, 0.25, 1) in linear RGB
  EXPECT_NEAR(pbr["baseColorFactor"][0].get<double>(), 0.21404, 1e-4);
  EXPECT_NEAR(pbr["baseColorFactor"][1].get<double>(), 0.05088, 1e-4);
  EXPECT_EQ(pbr["baseColorFactor"][2], 1.0);
  EXPECT_EQ(pbr["baseColorFactor"][3], 1.0);
  const json& fine = meshNamed(p, "fine_triangles")["primitives"][0];
  for (std::size_t k = 0; k < p.json["materials"].size(); ++k) {  // only the fine ones: both sides
    EXPECT_EQ(p.json["materials"][k]["doubleSided"].get<bool>(),
              fine["material"].get<std::size_t>() == k);
  }
}

TEST(MapGltf, FineTrianglesWithVertexColours) {
  const MapModel m = test::texturedRoomModel();
  const auto p = test::parseGlb(encodeMapGlb(m, true));
  const json& prim = meshNamed(p, "fine_triangles")["primitives"][0];
  const json& pos = p.json["accessors"][prim["attributes"]["POSITION"].get<int>()];
  EXPECT_EQ(pos["count"], m.fine.vertices.size());
  EXPECT_EQ(pos["min"], json({4.0, 0.0, 0.0}));
  EXPECT_EQ(pos["max"], json({4.0, 1.0, 1.0}));
  EXPECT_EQ(test::uintsOf(p, prim["indices"]), (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2}));
  const std::vector<float> rgb = test::floatsOf(p, prim["attributes"]["COLOR_0"]);
  EXPECT_EQ(rgb, (std::vector<float>{1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1}));
  EXPECT_FALSE(prim["attributes"].contains("NORMAL"));
}

const json& nodeNamed(const test::GlbParts& p, const std::string& name) {
  for (const json& n : p.json["nodes"]) {
    if (n.value("name", "") == name) {
      return n;
    }
  }
  throw std::runtime_error("no node " + name);
}

// viewer.html's inspector reads these (doc/viewer.md).
TEST(MapGltf, Item10_RectangleNodesCarrySurfaceIdTileAndSupport) {
  MapModel m = test::texturedRoomModel();
  m.support = {{3, 1200}, {7, 450}};  // surfaces 8 and 12: unknown
  const auto p = test::parseGlb(encodeMapGlb(m, true));
  for (const TexturedQuad& q : m.quads) {
    const json& extras =
        nodeNamed(p, "surface_" + std::to_string(q.surface_id) + "_" + std::to_string(q.tile))
            .at("extras");
    EXPECT_EQ(extras["surface_id"], q.surface_id);
    EXPECT_EQ(extras["tile"], q.tile);
    EXPECT_EQ(extras.contains("support"), q.surface_id == 3 || q.surface_id == 7) << extras;
  }
  EXPECT_EQ(nodeNamed(p, "surface_3_0")["extras"]["support"], 1200);
  EXPECT_EQ(nodeNamed(p, "surface_7_1")["extras"]["support"], 450);
  EXPECT_FALSE(nodeNamed(p, "fine_triangles").contains("extras"));
}

TEST(MapGltf, Item10_PathIsALineStripUnderTheRoot) {
  MapModel m = test::texturedRoomModel();
  m.path = {{1, 1, 0}, {2, 1.5, 0}, {3, 2, 0.25}};
  const auto p = test::parseGlb(encodeMapGlb(m, false));
  const json& prim = meshNamed(p, "robot_path")["primitives"][0];
  EXPECT_EQ(prim["mode"], 3);
  EXPECT_FALSE(prim.contains("indices"));
  const json& pos = p.json["accessors"][prim["attributes"]["POSITION"].get<int>()];
  EXPECT_EQ(pos["count"], 3);
  EXPECT_EQ(pos["min"], json({1.0, 1.0, 0.0}));
  EXPECT_EQ(pos["max"], json({3.0, 2.0, 0.25}));
  EXPECT_EQ(test::floatsOf(p, prim["attributes"]["POSITION"]),
            (std::vector<float>{1, 1, 0, 2, 1.5f, 0, 3, 2, 0.25f}));
  const json& root = p.json["nodes"][p.json["scenes"][0]["nodes"][0].get<int>()];
  bool under_root = false;
  for (const json& child : root["children"]) {
    under_root |= p.json["nodes"][child.get<int>()]["name"] == "robot_path";
  }
  EXPECT_TRUE(under_root);

  m.path.resize(1);  // one position is no line
  EXPECT_THROW(meshNamed(test::parseGlb(encodeMapGlb(m, false)), "robot_path"), std::runtime_error);
}

TEST(MapGltf, RootNodeTurnsZUpIntoYUp) {
  const auto p = test::parseGlb(encodeMapGlb(test::texturedRoomModel(), true));
  const json& scene = p.json["scenes"][p.json["scene"].get<int>()];
  ASSERT_EQ(scene["nodes"].size(), 1u);
  const json& root = p.json["nodes"][scene["nodes"][0].get<int>()];
  EXPECT_EQ(root["children"].size(), p.json["nodes"].size() - 1);
  const json& r = root["rotation"];  // (x, y, z, w)
  const Eigen::Quaterniond q(r[3].get<double>(), r[0].get<double>(), r[1].get<double>(),
                             r[2].get<double>());
  EXPECT_NEAR(q.norm(), 1.0, 1e-12);
  EXPECT_TRUE((q * Eigen::Vector3d::UnitZ()).isApprox(Eigen::Vector3d::UnitY(), 1e-12));
  EXPECT_TRUE((q * Eigen::Vector3d::UnitY()).isApprox(-Eigen::Vector3d::UnitZ(), 1e-12));
  EXPECT_TRUE((q * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitX(), 1e-12));
}

TEST(MapGltf, GeometryAloneHasNoTextures) {
  const MapModel m = test::texturedRoomModel();
  const auto textured = encodeMapGlb(m, true);
  const auto plain = encodeMapGlb(m, false);
  const auto p = test::parseGlb(plain);
  EXPECT_LT(plain.size(), textured.size());
  EXPECT_FALSE(p.json.contains("images"));
  EXPECT_FALSE(p.json.contains("textures"));
  EXPECT_FALSE(p.json.contains("samplers"));
  for (const json& material : p.json["materials"]) {
    EXPECT_TRUE(material["pbrMetallicRoughness"].contains("baseColorFactor"));
  }
  for (const json& mesh : p.json["meshes"]) {
    EXPECT_FALSE(mesh["primitives"][0]["attributes"].contains("TEXCOORD_0"));
  }
  const fs::path dir = test::freshDir("map_gltf_geometry");
  writeMapGeometryGlb(dir / "geometry.glb", m);
  EXPECT_EQ(readBytes(dir / "geometry.glb"), plain);
}

TEST(MapGltf, EmptyModelIsAGlbWithoutBinChunk) {
  const auto glb = encodeMapGlb(MapModel{}, true);
  const auto p = test::parseGlb(glb);
  EXPECT_EQ(p.length, glb.size());
  EXPECT_TRUE(p.bin.empty());
  EXPECT_FALSE(p.json.contains("buffers"));
  EXPECT_EQ(p.json["nodes"].size(), 1u);
  EXPECT_FALSE(p.json["nodes"][0].contains("children"));
}

TEST(MapGltf, WritesAtomicallyAndKeepsThePreviousFileOnFailure) {
  const fs::path dir = test::freshDir("map_gltf_atomic");
  const MapModel m = test::texturedRoomModel();
  writeMapGlb(dir / "map.glb", m, true);
  writeMapGlb(dir / "map.glb", m, true);
  EXPECT_EQ(readBytes(dir / "map.glb"), encodeMapGlb(m, true));
  EXPECT_EQ(test::filesBelow(dir), std::vector<std::string>{"map.glb"});
  fs::create_directory(dir / ("map.glb.tmp-" + std::to_string(::getpid())));
  EXPECT_THROW(writeMapGlb(dir / "map.glb", MapModel{}, true), OutputError);
  EXPECT_EQ(readBytes(dir / "map.glb"), encodeMapGlb(m, true));
  EXPECT_THROW(writeMapGlb(dir / "no-such-dir" / "map.glb", m, true), OutputError);
}

TEST(MapGltf, InvalidModelIsRejected) {
  MapModel m = test::texturedRoomModel();
  m.fine.colors.pop_back();
  EXPECT_THROW(encodeMapGlb(m, true), std::invalid_argument);
}

}  // namespace
}  // namespace pmap::products
