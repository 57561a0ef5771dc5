#include "pmap/products/map_model.h"

#include <cmath>
#include <limits>

namespace pmap::products {
namespace {

Eigen::Vector3d colourOf(const Eigen::Vector3d& normal) {
  const double vertical = std::abs(normal.z());
  return vertical < 0.2   ? Eigen::Vector3d(0.85, 0.83, 0.78)   // walls, doors
         : vertical > 0.9 ? Eigen::Vector3d(0.70, 0.78, 0.88)   // ceilings, floors
                          : Eigen::Vector3d(0.80, 0.70, 0.85);  // slanted
}

// +1 when the path position nearest to `centre` is on the normal's side.
double sideOfPath(const em::Rectangle& r, const std::vector<Eigen::Vector3d>& path) {
  double best = std::numeric_limits<double>::infinity();
  double side = 1.0;
  for (const Eigen::Vector3d& p : path) {
    const double d = (p - r.centre).squaredNorm();
    if (d < best) {
      best = d;
      side = r.planeDistance(p) >= 0 ? 1.0 : -1.0;
    }
  }
  return side;
}

}  // namespace

MapModel buildMapModel(const em::PlanarMap& map, const std::vector<Eigen::Vector3d>& points,
                       const std::vector<Eigen::Vector3d>& path) {
  MapModel m;
  for (const em::Surface& s : map.surfaces) {
    TexturedQuad q;
    q.surface_id = s.id;
    const auto c = s.rect.corners();
    q.normal = s.rect.normal;
    q.corners = c;
    if (sideOfPath(s.rect, path) < 0) {  // reversed along u: counter-clockwise from -normal
      q.normal = -s.rect.normal;
      q.corners = {c[1], c[0], c[3], c[2]};
    }
    q.color = colourOf(q.normal);
    m.quads.push_back(q);
    m.support[s.id] = s.support;
  }
  for (const em::Triangle& t : map.fine_triangles) {
    const auto base = static_cast<std::uint32_t>(m.fine.vertices.size());
    for (const std::int32_t i : t) {
      m.fine.vertices.push_back(points[static_cast<std::size_t>(i)]);
    }
    m.fine.triangles.push_back({base, base + 1, base + 2});
  }
  m.path = path;
  return m;
}

Eigen::AlignedBox3d boundingBox(const MapModel& model) {
  Eigen::AlignedBox3d box;
  for (const auto& q : model.quads) {
    for (const auto& c : q.corners) {
      box.extend(c);
    }
  }
  for (const auto& v : model.fine.vertices) {
    box.extend(v);
  }
  for (const auto& p : model.path) {
    box.extend(p);
  }
  return box;
}

}  // namespace pmap::products
