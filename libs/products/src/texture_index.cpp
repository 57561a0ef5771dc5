#include "pmap/products/texture_index.h"

#include <cstdio>

#include "pmap/common/atomic_file.h"
#include "pmap/products/texture_png.h"

namespace pmap::products {

void writeTexturesCsv(const std::filesystem::path& csv, const MapModel& model) {
  writeFileAtomically(csv, [&](std::ostream& out) {
    out << "file,surface_id,tile,width_px,height_px,x0,y0,z0,x1,y1,z1,x2,y2,z2,x3,y3,z3\n";
    char buf[96];
    for (const TexturedQuad& q : model.quads) {
      if (q.texture.empty()) {
        continue;
      }
      out << textureRelativePath(q.surface_id, q.tile) << "," << q.surface_id << "," << q.tile
          << "," << q.texture.cols << "," << q.texture.rows;
      for (const Eigen::Vector3d& c : q.corners) {
        std::snprintf(buf, sizeof buf, ",%.6f,%.6f,%.6f", c.x(), c.y(), c.z());
        out << buf;
      }
      out << "\n";
    }
  });
}

}  // namespace pmap::products
