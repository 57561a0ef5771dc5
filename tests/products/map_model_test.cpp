#include "pmap/products/map_model.h"

#include <gtest/gtest.h>

namespace pmap::products {
namespace {

em::Surface wall(std::int32_t id, std::int32_t support, double x) {
  em::Surface s;
  s.id = id;
  s.support = support;
  s.rect.centre = {x, 0, 1};
  s.rect.normal = Eigen::Vector3d::UnitX();
  s.rect.offset = x;
  s.rect.axis_u = Eigen::Vector3d::UnitY();
  s.rect.half_u = 1.0;
  s.rect.half_v = 1.0;
  return s;
}

// viewer.html's inspector shows each surface's support (through map.glb).
TEST(MapModel, Item10_CarriesEachSurfacesSupportAndThePath) {
  em::PlanarMap map;
  map.surfaces = {wall(4, 250, 1.0), wall(9, 31, -1.0)};  // the first is turned to the path
  const std::vector<Eigen::Vector3d> path = {{0, 0, 0}, {0.5, 0, 0}};
  const MapModel m = buildMapModel(map, {}, path);
  ASSERT_EQ(m.quads.size(), 2u);
  EXPECT_EQ(m.quads[0].normal, -Eigen::Vector3d::UnitX());
  EXPECT_EQ(m.support, (std::map<std::int32_t, std::int32_t>{{4, 250}, {9, 31}}));
  EXPECT_EQ(m.path, path);
}

}  // namespace
}  // namespace pmap::products
