// The planar map as glTF 2.0 binary (map.glb, doc/outputs.md): textures
// embedded as PNG, vertex data in world coordinates (metres, z up) under a
// root node that turns z-up into glTF's y-up.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "pmap/products/map_model.h"

namespace pmap::products {

/// The GLB bytes of `model`:
///  - one mesh and node per rectangle ("surface_<id>_<tile>"): two triangles
///    (c0 c1 c2, c0 c2 c3) with POSITION (min/max), NORMAL and, when its
///    texture is embedded, TEXCOORD_0 = (s, 1 - t) of map_model.h's convention;
///    node extras {"surface_id", "tile", "support" (when the model has it)};
///  - a textured rectangle (with `with_textures`) gets a material whose
///    baseColorTexture is its PNG, embedded in the BIN chunk (bufferView +
///    image/png); otherwise a baseColorFactor of its colour;
///  - the fine triangles as one mesh "fine_triangles" (no NORMAL: flat
///    normals), with COLOR_0 (float VEC3) when per-vertex colours are given;
///  - the path (two positions or more) as one mesh "robot_path": a line
///    strip (mode 3) of POSITION (min/max), coloured;
///  - rectangles single-sided (they face the robot, map_model.h), fine
///    triangles double-sided; metallic 0, roughness 1; colours taken as
///    sRGB and written linear (baseColorFactor and COLOR_0 are linear);
///  - every node a child of the root node "map", rotated -90 degrees about
///    x (z-up world to y-up glTF), the only node of the default scene.
/// Throws std::invalid_argument when the model breaks checkMapModel's
/// rules, OutputError when a texture cannot be encoded or the file would
/// exceed 4 GiB.
std::vector<std::uint8_t> encodeMapGlb(const MapModel& model, bool with_textures);

/// Writes encodeMapGlb(model, with_textures) to `glb` atomically; throws
/// OutputError naming the file (a previous file is then kept).
void writeMapGlb(const std::filesystem::path& glb, const MapModel& model, bool with_textures);

/// The same model's geometry alone (writeMapGlb with with_textures = false),
/// e.g. to compare file sizes with and without textures.
void writeMapGeometryGlb(const std::filesystem::path& glb, const MapModel& model);

}  // namespace pmap::products
