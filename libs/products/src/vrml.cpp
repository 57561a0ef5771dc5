#include "pmap/products/vrml.h"

#include <cstdio>

#include "pmap/common/atomic_file.h"

namespace pmap::products {
namespace {

void writeMesh(std::ostream& out, const VrmlMesh& m) {
  char buf[160];
  if (!m.name.empty()) {
    out << "DEF " << m.name << " ";
  }
  std::snprintf(buf, sizeof buf, "%.3f %.3f %.3f", m.color.x(), m.color.y(), m.color.z());
  out << "Shape {\n  appearance Appearance { material Material { diffuseColor " << buf
      << " } }\n  geometry IndexedFaceSet {\n    solid FALSE\n    coord Coordinate { point [\n";
  for (const auto& v : m.vertices) {
    std::snprintf(buf, sizeof buf, "      %.4f %.4f %.4f,\n", v.x(), v.y(), v.z());
    out << buf;
  }
  out << "    ] }\n    coordIndex [\n";
  for (const auto& t : m.triangles) {
    std::snprintf(buf, sizeof buf, "      %u %u %u -1,\n", t[0], t[1], t[2]);
    out << buf;
  }
  out << "    ]\n  }\n}\n";
}

}  // namespace

void writeVrml(const std::filesystem::path& path, const std::vector<VrmlMesh>& meshes,
               const std::string& comment) {
  writeFileAtomically(path, [&](std::ostream& out) {
    out << "#VRML V2.0 utf8\n";
    if (!comment.empty()) {
      out << "# " << comment << "\n";
    }
    for (const auto& m : meshes) {
      if (!m.triangles.empty()) {
        writeMesh(out, m);
      }
    }
  });
}

}  // namespace pmap::products
