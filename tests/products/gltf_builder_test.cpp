#include "pmap/products/gltf_builder.h"

#include <gtest/gtest.h>

#include "glb_reader.h"

namespace pmap::products {
namespace {

TEST(GltfBuilder, AssetAndNoBufferWhenEmpty) {
  GltfBuilder b("unit test");
  const auto p = test::parseGlb(b.glb());
  EXPECT_EQ(p.json["asset"]["version"], "2.0");
  EXPECT_EQ(p.json["asset"]["generator"], "unit test");
  EXPECT_FALSE(p.json.contains("buffers"));
  EXPECT_TRUE(p.bin.empty());
}

TEST(GltfBuilder, BufferViewsStartFourByteAligned) {
  GltfBuilder b("t");
  const std::vector<std::uint8_t> three{1, 2, 3};
  const std::vector<std::uint8_t> five{4, 5, 6, 7, 8};
  EXPECT_EQ(b.addBufferView(three, GltfBuilder::kNoTarget), 0);
  EXPECT_EQ(b.addBufferView(five, GltfBuilder::kArrayBuffer), 1);
  EXPECT_EQ(b.addBufferView(three, GltfBuilder::kElementArrayBuffer), 2);
  const auto p = test::parseGlb(b.glb());
  const auto& views = p.json["bufferViews"];
  EXPECT_EQ(views[0]["byteOffset"], 0);
  EXPECT_EQ(views[1]["byteOffset"], 4);
  EXPECT_EQ(views[2]["byteOffset"], 12);
  EXPECT_FALSE(views[0].contains("target"));
  EXPECT_EQ(views[1]["target"], 34962);
  EXPECT_EQ(views[2]["target"], 34963);
  EXPECT_EQ(p.json["buffers"][0]["byteLength"], 15);
  EXPECT_EQ(p.bin[3], 0);  // padding before view 1
  EXPECT_EQ(p.bin[4], 4);
}

TEST(GltfBuilder, ByteStrideOnlyWhenAsked) {
  GltfBuilder b("t");
  const std::vector<float> xyz(12, 1.0f);
  b.addBufferView(xyz, GltfBuilder::kArrayBuffer, 12);
  b.addBufferView(xyz, GltfBuilder::kArrayBuffer);
  const auto p = test::parseGlb(b.glb());
  EXPECT_EQ(p.json["bufferViews"][0]["byteStride"], 12);
  EXPECT_FALSE(p.json["bufferViews"][1].contains("byteStride"));
}

TEST(GltfBuilder, FloatAccessorBoundsPerComponent) {
  GltfBuilder b("t");
  const std::vector<float> xyz{9, 9, 9, 1, -2, 3, 4, 5, -6, 0.5f, 0, 0};
  const int view = b.addBufferView(xyz, GltfBuilder::kArrayBuffer);
  EXPECT_EQ(b.addFloatAccessor(view, 12, 3, 3, true), 0);  // skips the first vertex
  EXPECT_EQ(b.addFloatAccessor(view, 0, 6, 2, false), 1);
  const auto p = test::parseGlb(b.glb());
  const auto& a = p.json["accessors"];
  EXPECT_EQ(a[0]["byteOffset"], 12);
  EXPECT_EQ(a[0]["count"], 3);
  EXPECT_EQ(a[0]["type"], "VEC3");
  EXPECT_EQ(a[0]["componentType"], 5126);
  EXPECT_EQ(a[0]["min"], nlohmann::json({0.5, -2.0, -6.0}));
  EXPECT_EQ(a[0]["max"], nlohmann::json({4.0, 5.0, 3.0}));
  EXPECT_EQ(a[1]["type"], "VEC2");
  EXPECT_FALSE(a[1].contains("min"));
  EXPECT_EQ(test::floatsOf(p, 0), std::vector<float>(xyz.begin() + 3, xyz.end()));
}

TEST(GltfBuilder, IndexAccessorAndGenericArrays) {
  GltfBuilder b("t");
  const std::vector<std::uint32_t> idx{0, 1, 2, 2, 1, 3};
  const int view = b.addBufferView(idx, GltfBuilder::kElementArrayBuffer);
  EXPECT_EQ(b.addIndexAccessor(view, 12, 3), 0);
  EXPECT_EQ(b.add("nodes", {{"name", "a"}}), 0);
  EXPECT_EQ(b.add("nodes", {{"name", "b"}}), 1);
  const auto p = test::parseGlb(b.glb());
  EXPECT_EQ(p.json["accessors"][0]["componentType"], 5125);
  EXPECT_EQ(p.json["accessors"][0]["type"], "SCALAR");
  EXPECT_EQ(test::uintsOf(p, 0), (std::vector<std::uint32_t>{2, 1, 3}));
  EXPECT_EQ(p.json["nodes"][1]["name"], "b");
}

}  // namespace
}  // namespace pmap::products
