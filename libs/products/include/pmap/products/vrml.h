// VRML97 (ISO/IEC 14772) output: indexed face sets with a material colour.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace pmap::products {

struct VrmlMesh {
  std::string name;  ///< DEF name (optional)
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  Eigen::Vector3d color{0.8, 0.8, 0.8};  ///< diffuse RGB in [0, 1]
};

/// Writes the meshes as one VRML97 file (atomically; throws OutputError).
/// Each mesh is a Shape with an IndexedFaceSet (solid FALSE: both sides
/// drawn). Coordinates in metres with 0.1 mm resolution.
void writeVrml(const std::filesystem::path& path, const std::vector<VrmlMesh>& meshes,
               const std::string& comment = {});

}  // namespace pmap::products
