#include "pmap/products/planar_map_files.h"

#include <cmath>
#include <cstdio>

#include "pmap/common/atomic_file.h"

namespace pmap::products {

void writeSurfacesCsv(const std::filesystem::path& path, const std::vector<em::Surface>& surfaces) {
  writeFileAtomically(path, [&](std::ostream& out) {
    out << "id,nx,ny,nz,offset,x0,y0,z0,x1,y1,z1,x2,y2,z2,x3,y3,z3,support\n";
    char buf[128];
    for (const em::Surface& s : surfaces) {
      const em::Rectangle& r = s.rect;
      std::snprintf(buf, sizeof buf, "%d,%.9f,%.9f,%.9f,%.6f", s.id, r.normal.x(), r.normal.y(),
                    r.normal.z(), r.offset);
      out << buf;
      for (const Eigen::Vector3d& c : r.corners()) {
        std::snprintf(buf, sizeof buf, ",%.6f,%.6f,%.6f", c.x(), c.y(), c.z());
        out << buf;
      }
      out << "," << s.support << "\n";
    }
  });
}

std::vector<int> surfaceIdsOfPoints(const em::PlanarMap& map) {
  std::vector<int> ids(map.assignment.size(), -1);
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (map.assignment[i] >= 0) {
      ids[i] = map.surfaces[static_cast<std::size_t>(map.assignment[i])].id;
    }
  }
  return ids;
}

}  // namespace pmap::products
