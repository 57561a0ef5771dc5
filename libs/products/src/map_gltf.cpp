#include "pmap/products/map_gltf.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "pmap/common/atomic_file.h"
#include "pmap/common/error.h"
#include "pmap/products/gltf_builder.h"
#include "pmap/products/map_model_check.h"
#include "pmap/products/texture_png.h"

namespace pmap::products {
namespace {

constexpr std::uint32_t kQuadIndices[6] = {0, 1, 2, 0, 2, 3};
constexpr int kVec3Bytes = 3 * sizeof(float);      // also the byteStride of VEC3 views
constexpr double kSqrtHalf = 0.70710678118654752;  // sin(45 deg) = cos(45 deg)
constexpr int kLineStrip = 3;                      // primitive.mode
const Eigen::Vector3d kPathColour(0.9, 0.3, 0.1);  // sRGB

/// sRGB-encoded value in [0, 1] to linear (IEC 61966-2-1).
float srgbToLinear(double c) {
  c = std::clamp(c, 0.0, 1.0);
  return static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
}

void appendVec3(std::vector<float>& out, const Eigen::Vector3d& v) {
  out.insert(out.end(),
             {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())});
}

/// "surface_<id>_<tile>": mesh, node, image and material names.
std::string surfaceName(const TexturedQuad& q) {
  return "surface_" + std::to_string(q.surface_id) + "_" + std::to_string(q.tile);
}

/// Vertex data of all rectangles (4 vertices each, in quad order) and then of
/// the fine triangles; indices: the shared quad pattern, then the fine ones.
struct Streams {
  std::vector<float> positions, normals, colors;
  std::vector<std::uint32_t> indices{std::begin(kQuadIndices), std::end(kQuadIndices)};
};

Streams collectStreams(const MapModel& model) {
  Streams s;
  for (const TexturedQuad& q : model.quads) {
    const Eigen::Vector3d n = q.normal.normalized();
    for (const Eigen::Vector3d& c : q.corners) {
      appendVec3(s.positions, c);
      appendVec3(s.normals, n);
    }
  }
  if (model.fine.triangles.empty()) {
    return s;
  }
  for (const Eigen::Vector3d& v : model.fine.vertices) {
    appendVec3(s.positions, v);
  }
  for (const Eigen::Vector3f& c : model.fine.colors) {
    s.colors.insert(s.colors.end(),
                    {srgbToLinear(c.x()), srgbToLinear(c.y()), srgbToLinear(c.z())});
  }
  for (const auto& t : model.fine.triangles) {
    s.indices.insert(s.indices.end(), t.begin(), t.end());
  }
  return s;
}

/// Builds the document: buffer views first, then one mesh + node per part.
class MapGltfEncoder {
 public:
  MapGltfEncoder(const MapModel& model, bool with_textures)
      : model_(model), with_textures_(with_textures), gltf_("planar-mapper") {}

  std::vector<std::uint8_t> encode() {
    const Streams s = collectStreams(model_);
    if (!s.positions.empty()) {
      positions_ = gltf_.addBufferView(s.positions, GltfBuilder::kArrayBuffer, kVec3Bytes);
      indices_ = gltf_.addBufferView(s.indices, GltfBuilder::kElementArrayBuffer);
    }
    if (!s.normals.empty()) {
      normals_ = gltf_.addBufferView(s.normals, GltfBuilder::kArrayBuffer, kVec3Bytes);
    }
    if (!s.colors.empty()) {
      colors_ = gltf_.addBufferView(s.colors, GltfBuilder::kArrayBuffer, kVec3Bytes);
    }
    nlohmann::json children = nlohmann::json::array();
    for (std::size_t i = 0; i < model_.quads.size(); ++i) {
      children.push_back(quadNode(i));
    }
    if (!model_.fine.triangles.empty()) {
      children.push_back(fineNode(s.indices.size() - std::size(kQuadIndices)));
    }
    if (model_.path.size() >= 2) {
      children.push_back(pathNode());
    }
    // -90 degrees about x as (x, y, z, w): world z -> glTF y, world y -> -z.
    nlohmann::json root = {{"name", "map"}, {"rotation", {-kSqrtHalf, 0.0, 0.0, kSqrtHalf}}};
    if (!children.empty()) {
      root["children"] = std::move(children);
    }
    const int root_index = gltf_.add("nodes", std::move(root));
    gltf_.add("scenes", {{"nodes", {root_index}}});
    gltf_.json()["scene"] = 0;
    return gltf_.glb();
  }

 private:
  int quadNode(std::size_t i) {
    const TexturedQuad& q = model_.quads[i];
    const std::size_t first_vec3 = 4 * i * kVec3Bytes;
    nlohmann::json attributes = {
        {"POSITION", gltf_.addFloatAccessor(positions_, first_vec3, 4, 3, true)},
        {"NORMAL", gltf_.addFloatAccessor(normals_, first_vec3, 4, 3, false)}};
    int material = 0;
    if (with_textures_ && !q.texture.empty()) {
      attributes["TEXCOORD_0"] = quadTexCoordAccessor();
      material = textureMaterial(q);
    } else {
      material = colourMaterial(q.color, false);
    }
    const std::string name = q.surface_id >= 0 ? surfaceName(q) : "quad_" + std::to_string(i);
    return addMeshNode(name,
                       {{"attributes", std::move(attributes)},
                        {"indices", quadIndexAccessor()},
                        {"material", material},
                        {"mode", 4}},
                       quadExtras(q));
  }

  /// What viewers show of a rectangle (viewer.html's inspector).
  nlohmann::json quadExtras(const TexturedQuad& q) const {
    nlohmann::json extras = {{"surface_id", q.surface_id}, {"tile", q.tile}};
    const auto support = model_.support.find(q.surface_id);
    if (q.surface_id >= 0 && support != model_.support.end()) {
      extras["support"] = support->second;
    }
    return extras;
  }

  /// The robot path as one line strip "robot_path" (its own buffer view).
  int pathNode() {
    std::vector<float> xyz;
    for (const Eigen::Vector3d& p : model_.path) {
      appendVec3(xyz, p);
    }
    const int view = gltf_.addBufferView(xyz, GltfBuilder::kArrayBuffer);
    const nlohmann::json attributes = {
        {"POSITION", gltf_.addFloatAccessor(view, 0, model_.path.size(), 3, true)}};
    return addMeshNode("robot_path", {{"attributes", attributes},
                                      {"material", colourMaterial(kPathColour, false)},
                                      {"mode", kLineStrip}});
  }

  int fineNode(std::size_t index_count) {
    const std::size_t first_vertex = 4 * model_.quads.size();
    nlohmann::json attributes = {
        {"POSITION", gltf_.addFloatAccessor(positions_, first_vertex * kVec3Bytes,
                                            model_.fine.vertices.size(), 3, true)}};
    const bool per_vertex = !model_.fine.colors.empty();
    if (per_vertex) {
      attributes["COLOR_0"] =
          gltf_.addFloatAccessor(colors_, 0, model_.fine.colors.size(), 3, false);
    }
    const int material =
        colourMaterial(per_vertex ? Eigen::Vector3d::Ones() : model_.fine.color, true);
    const int indices = gltf_.addIndexAccessor(
        indices_, std::size(kQuadIndices) * sizeof(std::uint32_t), index_count);
    return addMeshNode("fine_triangles", {{"attributes", std::move(attributes)},
                                          {"indices", indices},
                                          {"material", material},
                                          {"mode", 4}});
  }

  int addMeshNode(const std::string& name, nlohmann::json primitive,
                  nlohmann::json extras = nullptr) {
    const int mesh = gltf_.add("meshes", {{"name", name}, {"primitives", {std::move(primitive)}}});
    nlohmann::json node = {{"name", name}, {"mesh", mesh}};
    if (!extras.is_null()) {
      node["extras"] = std::move(extras);
    }
    return gltf_.add("nodes", std::move(node));
  }

  int quadIndexAccessor() {
    if (quad_indices_ < 0) {
      quad_indices_ = gltf_.addIndexAccessor(indices_, 0, std::size(kQuadIndices));
    }
    return quad_indices_;
  }

  int quadTexCoordAccessor() {
    if (quad_uvs_ < 0) {
      std::vector<float> uv;
      for (const Eigen::Vector2f& st : quadTexCoords()) {
        uv.insert(uv.end(), {st.x(), 1.0f - st.y()});  // glTF UV = (s, 1 - t)
      }
      const int view = gltf_.addBufferView(uv, GltfBuilder::kArrayBuffer);
      quad_uvs_ = gltf_.addFloatAccessor(view, 0, 4, 2, false);
    }
    return quad_uvs_;
  }

  int colourMaterial(const Eigen::Vector3d& srgb, bool double_sided) {
    const std::array<float, 3> linear{srgbToLinear(srgb.x()), srgbToLinear(srgb.y()),
                                      srgbToLinear(srgb.z())};
    const auto key = std::make_pair(linear, double_sided);
    const auto found = colour_materials_.find(key);
    if (found != colour_materials_.end()) {
      return found->second;
    }
    const int index =
        addMaterial({{"baseColorFactor", {linear[0], linear[1], linear[2], 1.0f}}}, double_sided);
    colour_materials_.emplace(key, index);
    return index;
  }

  int textureMaterial(const TexturedQuad& q) {
    if (sampler_ < 0) {  // clamp: a texture covers exactly its rectangle
      sampler_ =
          gltf_.add("samplers",
                    {{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 33071}, {"wrapT", 33071}});
    }
    const std::vector<std::uint8_t> png = encodePng(q.texture);
    const int view = gltf_.addBufferView(png, GltfBuilder::kNoTarget);
    const std::string name = surfaceName(q);
    const int image =
        gltf_.add("images", {{"name", name}, {"bufferView", view}, {"mimeType", "image/png"}});
    const int texture = gltf_.add("textures", {{"sampler", sampler_}, {"source", image}});
    return addMaterial({{"baseColorTexture", {{"index", texture}}}}, false, name);
  }

  // Rectangles face the robot's side (map_model.h) and are single-sided, so
  // a viewer looking from outside sees into the rooms; the fine triangles'
  // orientation is arbitrary: double-sided.
  int addMaterial(nlohmann::json pbr, bool double_sided, const std::string& name = {}) {
    pbr["metallicFactor"] = 0.0;
    pbr["roughnessFactor"] = 1.0;
    nlohmann::json material = {{"pbrMetallicRoughness", std::move(pbr)},
                               {"doubleSided", double_sided}};
    if (!name.empty()) {
      material["name"] = name;
    }
    return gltf_.add("materials", std::move(material));
  }

  const MapModel& model_;
  const bool with_textures_;
  GltfBuilder gltf_;
  int positions_ = -1, normals_ = -1, colors_ = -1, indices_ = -1;
  int quad_indices_ = -1, quad_uvs_ = -1, sampler_ = -1;
  std::map<std::pair<std::array<float, 3>, bool>, int> colour_materials_;
};

}  // namespace

std::vector<std::uint8_t> encodeMapGlb(const MapModel& model, bool with_textures) {
  checkMapModel(model);
  return MapGltfEncoder(model, with_textures).encode();
}

void writeMapGlb(const std::filesystem::path& glb, const MapModel& model, bool with_textures) {
  std::vector<std::uint8_t> bytes;
  try {
    bytes = encodeMapGlb(model, with_textures);
  } catch (const OutputError& e) {
    throw OutputError(glb.string() + ": " + e.what());
  }
  writeFileAtomically(
      glb,
      [&](std::ostream& out) {
        out.write(reinterpret_cast<const char*>(bytes.data()),
                  static_cast<std::streamsize>(bytes.size()));
      },
      /*binary=*/true);
}

void writeMapGeometryGlb(const std::filesystem::path& glb, const MapModel& model) {
  writeMapGlb(glb, model, /*with_textures=*/false);
}

}  // namespace pmap::products
