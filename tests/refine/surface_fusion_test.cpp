#include "pmap/refine/surface_fusion.h"

#include <gtest/gtest.h>

#include <cmath>

#include "refine_world.h"

namespace pmap::refine {
namespace {

using testing::rectangle;
const Eigen::Vector3d kX = Eigen::Vector3d::UnitX();

// Points on two rectangles, the map holding them as two surfaces.
em::PlanarMap twoSurfaceMap(const em::Rectangle& a, const em::Rectangle& b,
                            std::vector<Eigen::Vector3d>& points) {
  std::mt19937 rng(21);
  em::PlanarMap map;
  int id = 0;
  for (const em::Rectangle& r : {a, b}) {
    const std::size_t first = points.size();
    testing::addPoints(r, 0.05, 0.02, rng, points);
    map.assignment.resize(points.size(), id);
    map.surfaces.push_back({r, id, static_cast<std::int32_t>(points.size() - first), false});
    ++id;
  }
  map.explained_fraction = 1.0;
  return map;
}

TEST(FusionOptions, TolerancesFollowSigma) {
  em::PlanarEmOptions em;
  em.sigma_m = 0.02;
  RefineOptions o;
  const em::PlanarEmOptions f = fusionOptions(em, o);
  EXPECT_NEAR(f.fuse_offset_m, 0.10, 1e-12);
  EXPECT_NEAR(f.fuse_angle_deg, std::atan(0.10) * 180.0 / M_PI, 1e-12);
  em.sigma_m = 0.05;
  EXPECT_NEAR(fusionOptions(em, o).fuse_offset_m, 0.25, 1e-12);
}

TEST(FuseSurfaces, TwoPiecesOfOneWallBecomeOne) {
  // One wall, 6 m long, held as two pieces side by side (a split wall).
  std::vector<Eigen::Vector3d> points;
  em::PlanarMap map =
      twoSurfaceMap(rectangle(Eigen::Vector3d::UnitY(), {1.5, 0, 1.3}, kX, 1.5, 1.3),
                    rectangle(Eigen::Vector3d::UnitY(), {4.55, 0.005, 1.3}, kX, 1.45, 1.3), points);
  em::PlanarEmOptions em;
  em.min_rows = 1;
  const FusionResult r =
      fuseSurfaces(points, em::nearestNeighbours(points, 0.1), {}, em, RefineOptions{}, map);
  EXPECT_EQ(r.changed_pairs, 1);
  ASSERT_EQ(map.surfaces.size(), 1u);
  EXPECT_EQ(r.replaced_ids, (std::vector<std::int32_t>{0, 1}));
  EXPECT_EQ(r.new_ids, (std::vector<std::int32_t>{2}));
  double x_min = INFINITY, x_max = -INFINITY;
  for (const Eigen::Vector3d& c : map.surfaces[0].rect.corners()) {
    x_min = std::min(x_min, c.x());
    x_max = std::max(x_max, c.x());
  }
  EXPECT_NEAR(x_max - x_min, 6.0, 0.05);  // the fused rectangle spans both pieces
  std::size_t on_fused = 0;
  for (const std::int32_t a : map.assignment) {
    EXPECT_LE(a, 0);
    on_fused += a == 0 ? 1 : 0;
  }
  EXPECT_GE(on_fused, points.size() * 99 / 100);
}

TEST(FuseSurfaces, ADoorRecessedBehindItsWallStaysApart) {
  // 20 cm behind the wall: ten sigma, beyond the 5-sigma tolerance.
  std::vector<Eigen::Vector3d> points;
  em::PlanarMap map =
      twoSurfaceMap(rectangle(Eigen::Vector3d::UnitY(), {1.5, 0, 1.3}, kX, 1.5, 1.3),
                    rectangle(Eigen::Vector3d::UnitY(), {3.5, 0.2, 1.0}, kX, 0.45, 1.0), points);
  em::PlanarEmOptions em;
  em.min_rows = 1;
  const FusionResult r =
      fuseSurfaces(points, em::nearestNeighbours(points, 0.1), {}, em, RefineOptions{}, map);
  EXPECT_EQ(r.changed_pairs, 0);
  EXPECT_EQ(map.surfaces.size(), 2u);
  EXPECT_TRUE(r.replaced_ids.empty());
}

}  // namespace
}  // namespace pmap::refine
