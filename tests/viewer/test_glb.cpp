#include "test_glb.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>
#include <string>

namespace pmap::viewer::testing {
namespace {

using nlohmann::json;

constexpr int kFloat = 5126;
constexpr int kUnsignedShort = 5123;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;

/// The binary chunk and the JSON arrays that describe it.
struct GlbBuilder {
  std::vector<std::uint8_t> bin;
  json buffer_views = json::array();
  json accessors = json::array();

  int addView(const void* data, std::size_t size, int target) {
    while (bin.size() % 4 != 0) {
      bin.push_back(0);
    }
    const std::size_t offset = bin.size();
    bin.resize(offset + size);
    std::memcpy(bin.data() + offset, data, size);
    json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}};
    if (target != 0) {
      view["target"] = target;
    }
    buffer_views.push_back(view);
    return int(buffer_views.size()) - 1;
  }

  int addFloats(const std::vector<float>& values, int components, const char* type) {
    const int view = addView(values.data(), values.size() * sizeof(float), kArrayBuffer);
    json accessor = {{"bufferView", view},
                     {"componentType", kFloat},
                     {"count", values.size() / components},
                     {"type", type}};
    if (components == 3) {  // POSITION needs its bounds
      std::vector<float> lo(3, 1e30f), hi(3, -1e30f);
      for (std::size_t i = 0; i < values.size(); ++i) {
        lo[i % 3] = std::min(lo[i % 3], values[i]);
        hi[i % 3] = std::max(hi[i % 3], values[i]);
      }
      accessor["min"] = lo;
      accessor["max"] = hi;
    }
    accessors.push_back(accessor);
    return int(accessors.size()) - 1;
  }

  int addIndices(const std::vector<std::uint16_t>& indices) {
    const int view =
        addView(indices.data(), indices.size() * sizeof(std::uint16_t), kElementArrayBuffer);
    accessors.push_back({{"bufferView", view},
                         {"componentType", kUnsignedShort},
                         {"count", indices.size()},
                         {"type", "SCALAR"}});
    return int(accessors.size()) - 1;
  }
};

std::vector<std::uint8_t> checkerboardPng() {
  cv::Mat image(64, 64, CV_8UC3);
  for (int r = 0; r < image.rows; ++r) {
    for (int c = 0; c < image.cols; ++c) {
      const bool dark = ((r / 8) + (c / 8)) % 2 == 0;
      image.at<cv::Vec3b>(r, c) = dark ? cv::Vec3b(60, 90, 150) : cv::Vec3b(230, 220, 200);
    }
  }
  std::vector<std::uint8_t> png;
  if (!cv::imencode(".png", image, png)) {
    throw std::runtime_error("test GLB: cannot encode the texture");
  }
  return png;
}

json quadPrimitive(GlbBuilder& glb, const TestQuad& quad, int material) {
  const Eigen::Vector3f normal =
      (quad.corners[1] - quad.corners[0]).cross(quad.corners[3] - quad.corners[0]).normalized();
  std::vector<float> positions, normals;
  for (const Eigen::Vector3f& c : quad.corners) {
    positions.insert(positions.end(), {c.x(), c.y(), c.z()});
    normals.insert(normals.end(), {normal.x(), normal.y(), normal.z()});
  }
  // glTF UV (s, 1 - t) for (s, t) = (0,0) (1,0) (1,1) (0,1).
  const std::vector<float> uv = {0, 1, 1, 1, 1, 0, 0, 0};
  json attributes = {{"POSITION", glb.addFloats(positions, 3, "VEC3")},
                     {"NORMAL", glb.addFloats(normals, 3, "VEC3")}};
  if (quad.textured) {
    attributes["TEXCOORD_0"] = glb.addFloats(uv, 2, "VEC2");
  }
  return {{"attributes", attributes},
          {"indices", glb.addIndices({0, 1, 2, 0, 2, 3})},
          {"material", material}};
}

json quadMaterial(const TestQuad& quad) {
  json pbr = {{"metallicFactor", 0.0}, {"roughnessFactor", 0.9}};
  if (quad.textured) {
    pbr["baseColorTexture"] = {{"index", 0}};
  } else {
    pbr["baseColorFactor"] = {quad.color.x(), quad.color.y(), quad.color.z(), 1.0};
  }
  return {{"pbrMetallicRoughness", pbr}, {"doubleSided", true}};
}

void appendChunk(std::vector<std::uint8_t>& out, std::vector<std::uint8_t> data, char pad,
                 const char* type) {
  while (data.size() % 4 != 0) {
    data.push_back(std::uint8_t(pad));
  }
  const std::uint32_t length = std::uint32_t(data.size());
  out.insert(out.end(), reinterpret_cast<const std::uint8_t*>(&length),
             reinterpret_cast<const std::uint8_t*>(&length) + 4);
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data.begin(), data.end());
}

}  // namespace

std::vector<std::uint8_t> makeQuadsGlb(const std::vector<TestQuad>& quads) {
  GlbBuilder glb;
  json primitives = json::array(), materials = json::array();
  for (const TestQuad& quad : quads) {
    materials.push_back(quadMaterial(quad));
    primitives.push_back(quadPrimitive(glb, quad, int(materials.size()) - 1));
  }
  const std::vector<std::uint8_t> png = checkerboardPng();
  const int image_view = glb.addView(png.data(), png.size(), 0);
  const double h = std::sqrt(0.5);
  json gltf = {
      {"asset", {{"version", "2.0"}, {"generator", "pmap viewer tests"}}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0}}}}},
      {"nodes",
       {{{"name", "z-up to y-up"}, {"rotation", {-h, 0, 0, h}}, {"children", {1}}},
        {{"name", "map"}, {"mesh", 0}}}},
      {"meshes", {{{"primitives", primitives}}}},
      {"materials", materials},
      {"images", {{{"bufferView", image_view}, {"mimeType", "image/png"}}}},
      {"samplers", {{{"magFilter", 9728}, {"minFilter", 9728}}}},
      {"textures", {{{"source", 0}, {"sampler", 0}}}},
      {"accessors", glb.accessors},
      {"bufferViews", glb.buffer_views},
  };
  gltf["buffers"] = {{{"byteLength", glb.bin.size() + (4 - glb.bin.size() % 4) % 4}}};
  const std::string text = gltf.dump();
  std::vector<std::uint8_t> out = {'g', 'l', 'T', 'F', 2, 0, 0, 0, 0, 0, 0, 0};
  appendChunk(out, std::vector<std::uint8_t>(text.begin(), text.end()), ' ', "JSON");
  appendChunk(out, glb.bin, 0, "BIN\0");
  const std::uint32_t total = std::uint32_t(out.size());
  std::memcpy(out.data() + 8, &total, 4);
  return out;
}

std::vector<TestQuad> corridorQuads(int segments) {
  std::vector<TestQuad> quads;
  const float w = 1.0f, h = 2.5f;
  for (int i = 0; i < segments; ++i) {
    const float x0 = 2.0f * float(i), x1 = x0 + 2.0f;
    TestQuad floor{{{{x0, -w, 0}, {x1, -w, 0}, {x1, w, 0}, {x0, w, 0}}}, {0.55f, 0.55f, 0.5f}};
    TestQuad right{{{{x1, -w, 0}, {x0, -w, 0}, {x0, -w, h}, {x1, -w, h}}}, {0.85f, 0.5f, 0.3f}};
    TestQuad left{{{{x0, w, 0}, {x1, w, 0}, {x1, w, h}, {x0, w, h}}}, {0.3f, 0.6f, 0.85f}};
    for (TestQuad* quad : {&floor, &right, &left}) {
      quad->textured = quads.size() % 4 == 1;
      quads.push_back(*quad);
    }
  }
  return quads;
}

std::vector<Eigen::Vector3f> pointsOnQuads(const std::vector<TestQuad>& quads, std::size_t count,
                                           std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::normal_distribution<float> noise(0.0f, 0.01f);
  std::vector<Eigen::Vector3f> points;
  points.reserve(count);
  if (quads.empty()) {
    return points;
  }
  std::uniform_int_distribution<std::size_t> pick(0, quads.size() - 1);
  for (std::size_t i = 0; i < count; ++i) {
    const TestQuad& q = quads[pick(rng)];
    const float s = unit(rng), t = unit(rng);
    const Eigen::Vector3f p =
        q.corners[0] + s * (q.corners[1] - q.corners[0]) + t * (q.corners[3] - q.corners[0]);
    points.push_back(p + Eigen::Vector3f(noise(rng), noise(rng), noise(rng)));
  }
  return points;
}

}  // namespace pmap::viewer::testing
