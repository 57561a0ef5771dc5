#include "test_flat.h"

namespace pmap::viewer::testing {
namespace {

em::Surface surface(std::int32_t id, const Eigen::Vector3d& centre, const Eigen::Vector3d& normal,
                    const Eigen::Vector3d& axis_u, double half_u, double half_v) {
  em::Surface s;
  s.id = id;
  s.support = flatSupport(id);
  s.rect.centre = centre;
  s.rect.normal = normal;
  s.rect.offset = normal.dot(centre);
  s.rect.axis_u = axis_u;
  s.rect.half_u = half_u;
  s.rect.half_v = half_v;
  return s;
}

const std::vector<Eigen::Vector3d> kPath = {{1, 1, 0}, {3, 2.5, 0}, {5, 2.5, 0}, {7, 4, 0}};

/// Cuts quad `index` into two tiles along c0 -> c1 (as the texturer does).
void splitIntoTiles(products::MapModel& m, std::size_t index) {
  products::TexturedQuad first = m.quads[index];
  products::TexturedQuad second = first;
  const auto c = first.corners;
  const Eigen::Vector3d mid01 = (c[0] + c[1]) / 2, mid32 = (c[3] + c[2]) / 2;
  first.corners = {c[0], mid01, mid32, c[3]};
  second.corners = {mid01, c[1], c[2], mid32};
  second.tile = 1;
  m.quads[index] = first;
  m.quads.insert(m.quads.begin() + static_cast<std::ptrdiff_t>(index) + 1, second);
}

}  // namespace

products::MapModel flatModel() {
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(),
                        z = Eigen::Vector3d::UnitZ();
  em::PlanarMap map;
  map.surfaces = {
      surface(kFloor, {4, 2.5, 0}, z, x, 4, 2.5),
      surface(kCeiling, {4, 2.5, 2.5}, z, x, 4, 2.5),
      surface(kSouthWall, {4, 0, 1.25}, y, x, 4, 1.25),
      surface(kNorthWall, {4, 5, 1.25}, y, x, 4, 1.25),
      surface(kWestWall, {0, 2.5, 1.25}, x, y, 2.5, 1.25),
      surface(kEastWall, {8, 2.5, 1.25}, x, y, 2.5, 1.25),
      surface(kInnerWallSouth, {4, 1, 1.25}, x, y, 1, 1.25),
      surface(kInnerWallNorth, {4, 4, 1.25}, x, y, 1, 1.25),
  };
  products::MapModel m = products::buildMapModel(map, {}, kPath);
  splitIntoTiles(m, kNorthWall);
  return m;
}

double flatPathLength() {
  double length = 0;
  for (std::size_t i = 1; i < kPath.size(); ++i) {
    length += (kPath[i] - kPath[i - 1]).norm();
  }
  return length;
}

}  // namespace pmap::viewer::testing
