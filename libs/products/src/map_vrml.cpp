#include "pmap/products/map_vrml.h"

#include <algorithm>
#include <cstdio>
#include <ostream>

#include "pmap/common/atomic_file.h"
#include "pmap/products/map_model_check.h"
#include "pmap/products/texture_png.h"

namespace pmap::products {
namespace {

std::string rgb(double r, double g, double b) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3f %.3f %.3f", std::clamp(r, 0.0, 1.0), std::clamp(g, 0.0, 1.0),
                std::clamp(b, 0.0, 1.0));
  return buf;
}

void writePoint(std::ostream& out, const Eigen::Vector3d& v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "      %.4f %.4f %.4f,\n", v.x(), v.y(), v.z());
  out << buf;
}

void writeQuad(std::ostream& out, const TexturedQuad& q) {
  if (q.surface_id >= 0) {
    out << "DEF surface_" << q.surface_id << "_" << q.tile << " ";
  }
  out << "Shape {\n  appearance Appearance {\n";
  if (q.texture.empty()) {
    out << "    material Material { diffuseColor " << rgb(q.color.x(), q.color.y(), q.color.z())
        << " }\n";
  } else {
    out << "    material Material { diffuseColor 1 1 1 }\n"
        << "    texture ImageTexture { url \"" << textureRelativePath(q.surface_id, q.tile)
        << "\" repeatS FALSE repeatT FALSE }\n";
  }
  out << "  }\n  geometry IndexedFaceSet {\n    solid FALSE\n    coord Coordinate { point [\n";
  for (const Eigen::Vector3d& c : q.corners) {
    writePoint(out, c);
  }
  out << "    ] }\n    texCoord TextureCoordinate { point [";
  for (const Eigen::Vector2f& st : quadTexCoords()) {
    out << " " << st.x() << " " << st.y() << ",";
  }
  out << " ] }\n    coordIndex [ 0 1 2 -1, 0 2 3 -1 ]\n"
      << "    texCoordIndex [ 0 1 2 -1, 0 2 3 -1 ]\n  }\n}\n";
}

void writeFine(std::ostream& out, const ColoredTriangles& fine) {
  const bool per_vertex = !fine.colors.empty();
  out << "DEF fine_triangles Shape {\n  appearance Appearance { material Material { diffuseColor "
      << (per_vertex ? "1 1 1" : rgb(fine.color.x(), fine.color.y(), fine.color.z()))
      << " } }\n  geometry IndexedFaceSet {\n    solid FALSE\n";
  out << "    coord Coordinate { point [\n";
  for (const Eigen::Vector3d& v : fine.vertices) {
    writePoint(out, v);
  }
  out << "    ] }\n";
  if (per_vertex) {
    out << "    colorPerVertex TRUE\n    color Color { color [\n";
    for (const Eigen::Vector3f& c : fine.colors) {
      out << "      " << rgb(c.x(), c.y(), c.z()) << ",\n";
    }
    out << "    ] }\n";
  }
  out << "    coordIndex [\n";
  char buf[80];
  for (const auto& t : fine.triangles) {
    std::snprintf(buf, sizeof buf, "      %u %u %u -1,\n", t[0], t[1], t[2]);
    out << buf;
  }
  out << "    ]\n  }\n}\n";
}

void writeComment(std::ostream& out, const std::string& comment) {
  std::size_t begin = 0;
  while (begin < comment.size()) {
    const std::size_t end = std::min(comment.find('\n', begin), comment.size());
    out << "# " << comment.substr(begin, end - begin) << "\n";
    begin = end + 1;
  }
}

void writeTextures(const std::filesystem::path& wrl, const MapModel& model) {
  const auto textured = [](const TexturedQuad& q) { return !q.texture.empty(); };
  if (std::none_of(model.quads.begin(), model.quads.end(), textured)) {
    return;
  }
  ensureWritableDirectory(wrl.parent_path() / kTextureDir);
  for (const TexturedQuad& q : model.quads) {
    if (textured(q)) {
      writePngAtomically(wrl.parent_path() / textureRelativePath(q.surface_id, q.tile), q.texture);
    }
  }
}

}  // namespace

void writeMapVrml(const std::filesystem::path& wrl, const MapModel& model,
                  const std::string& comment) {
  checkMapModel(model);
  writeTextures(wrl, model);
  writeFileAtomically(wrl, [&](std::ostream& out) {
    out << "#VRML V2.0 utf8\n";
    writeComment(out, comment);
    for (const TexturedQuad& q : model.quads) {
      writeQuad(out, q);
    }
    if (!model.fine.triangles.empty()) {
      writeFine(out, model.fine);
    }
  });
}

}  // namespace pmap::products
