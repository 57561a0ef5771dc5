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

std::vector<VrmlMesh> planarMapMeshes(const em::PlanarMap& map,
                                      const std::vector<Eigen::Vector3d>& points) {
  std::vector<VrmlMesh> meshes;
  for (const em::Surface& s : map.surfaces) {
    VrmlMesh m;
    m.name = "Surface" + std::to_string(s.id);
    const auto c = s.rect.corners();
    m.vertices.assign(c.begin(), c.end());
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    const double vertical = std::abs(s.rect.normal.z());
    m.color = vertical < 0.2   ? Eigen::Vector3d(0.85, 0.83, 0.78)   // walls, doors
              : vertical > 0.9 ? Eigen::Vector3d(0.70, 0.78, 0.88)   // ceilings, floors
                               : Eigen::Vector3d(0.80, 0.70, 0.85);  // slanted
    meshes.push_back(std::move(m));
  }
  if (!map.fine_triangles.empty()) {
    VrmlMesh fine;
    fine.name = "FineTriangles";
    fine.color = {0.75, 0.25, 0.2};
    for (const em::Triangle& t : map.fine_triangles) {
      const auto base = static_cast<std::uint32_t>(fine.vertices.size());
      for (const std::int32_t i : t) {
        fine.vertices.push_back(points[static_cast<std::size_t>(i)]);
      }
      fine.triangles.push_back({base, base + 1, base + 2});
    }
    meshes.push_back(std::move(fine));
  }
  return meshes;
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
