#include "pmap/refine/map_refiner.h"

#include <gtest/gtest.h>

#include "refine_world.h"

namespace pmap::refine {
namespace {

em::PlanarMap mapOf(const testing::Scene& scene) {
  em::PlanarMap map;
  map.surfaces = scene.surfaces;
  map.assignment.assign(scene.points.size(), -1);
  for (std::size_t j = 0; j < scene.samples.size(); ++j) {
    for (const SurfaceSample& s : scene.samples[j]) {
      map.assignment[static_cast<std::size_t>(s.point)] = static_cast<std::int32_t>(j);
    }
  }
  return map;
}

TEST(RefineMap, DisabledLeavesTheMapAlone) {
  const testing::Scene scene = testing::wallUnderCeiling(0.02);
  em::PlanarMap map = mapOf(scene);
  RefineOptions o;
  o.enabled = false;
  const RefineResult r = refineMap(scene.points, em::nearestNeighbours(scene.points, 0.1), {},
                                   em::PlanarEmOptions{}, o, map);
  EXPECT_FALSE(r.ran);
  EXPECT_EQ(r.message, "disabled");
  EXPECT_EQ(map.surfaces[0].rect.centre, scene.surfaces[0].rect.centre);
}

TEST(RefineMap, FusesThenClosesTheSeamWithTheEStepWeights) {
  const testing::Scene scene = testing::wallUnderCeiling(0.02);
  em::PlanarMap map = mapOf(scene);
  em::PlanarEmOptions em;
  em.min_rows = 1;
  const RefineResult r = refineMap(scene.points, em::nearestNeighbours(scene.points, 0.1), {}, em,
                                   RefineOptions{}, map);
  EXPECT_TRUE(r.ran);
  EXPECT_EQ(r.fusion.changed_pairs, 0);  // a wall and a ceiling are not one plane
  EXPECT_EQ(r.boundaries.seams.size(), 2u);
  EXPECT_EQ(r.boundaries.termination, "CONVERGENCE");
  const em::Rectangle& wall = map.surfaces[0].rect;
  EXPECT_NEAR(wall.centre.z() + wall.half_v, 2.7, 0.01);
  EXPECT_NE(r.message.find("2 seams"), std::string::npos) << r.message;
}

TEST(RefineMap, NoSurfacesIsNotAnError) {
  em::PlanarMap map;
  const RefineResult r = refineMap({}, {}, {}, em::PlanarEmOptions{}, RefineOptions{}, map);
  EXPECT_FALSE(r.ran);
  EXPECT_EQ(r.message, "no surfaces");
}

}  // namespace
}  // namespace pmap::refine
