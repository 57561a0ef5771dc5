// The shared decisions of model selection (selection_policy.h): the same
// functions serve the offline selector and the online EM.
#include "pmap/em/selection_policy.h"

#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <string>
#include <vector>

#include "em_test_worlds.h"
#include "pmap/em/surface_fit.h"

namespace pmap::em {
namespace {

using testing::allIndices;

Rectangle fitted(const testing::Cloud& c) {
  Rectangle r;
  EXPECT_EQ(fitSurface(c.points, allIndices(c.points.size()), r), FitStatus::kOk);
  return r;
}

TEST(SelectionPolicy, Item14_PosteriorGainIsEq30) {
  PlanarEmOptions o;
  o.kappa = 200.0;
  o.empty_area_cost = 20.0;
  o.min_gain = 10.0;
  // Removing a surface (-1) saves kappa; leaving 2 m^2 less empty saves 40 nats.
  EXPECT_DOUBLE_EQ(posteriorGain(-100.0, -1, -2.0, o), -100.0 + 200.0 + 40.0);
  // Adding one costs kappa.
  EXPECT_DOUBLE_EQ(posteriorGain(300.0, 1, 0.0, o), 100.0);
  EXPECT_TRUE(raisesPosterior(10.5, o));
  EXPECT_FALSE(raisesPosterior(10.0, o));  // hysteresis: more than min_gain
  EXPECT_TRUE(recutAffordable(-9.0, o));
  EXPECT_FALSE(recutAffordable(-10.0, o));
}

TEST(SelectionPolicy, Item14_RecutRulesUseTheirPercentages) {
  PlanarEmOptions o;  // 5 % growth, 90 % transfer at most
  EXPECT_FALSE(recutGrowsLarger(105, 100, o));
  EXPECT_TRUE(recutGrowsLarger(106, 100, o));
  EXPECT_TRUE(recutLeavesSmaller(90, 100, o));
  EXPECT_FALSE(recutLeavesSmaller(91, 100, o));
  o.rules.recut_min_growth_percent = 0;
  EXPECT_TRUE(recutGrowsLarger(101, 100, o));
}

TEST(SelectionPolicy, Item14_FusionPartnersAreCoplanarAndClose) {
  std::mt19937_64 rng(1);
  testing::Cloud a, b, far, tilted;
  testing::addPlane(a, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 2.0, 2.0, 0.1, 0.0, rng);
  testing::addPlane(b, {2.3, 0.02, 0}, {1, 0, 0}, {0, 0, 1}, 2.0, 2.0, 0.1, 0.0, rng);
  testing::addPlane(far, {5.0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 2.0, 2.0, 0.1, 0.0, rng);
  testing::addPlane(tilted, {2.3, 0, 0}, Eigen::Vector3d(1, 0.5, 0).normalized(), {0, 0, 1}, 2.0,
                    2.0, 0.1, 0.0, rng);
  const PlanarEmOptions o;
  EXPECT_TRUE(fusionPartners(fitted(a), fitted(b), o));
  EXPECT_FALSE(fusionPartners(fitted(a), fitted(far), o));     // 3 m apart
  EXPECT_FALSE(fusionPartners(fitted(a), fitted(tilted), o));  // 27 degrees
  EXPECT_NEAR(rectangleGap(fitted(a), fitted(b)), 0.3, 0.03);
}

TEST(SelectionPolicy, Item14_RowsAreCountedUpToMinRows) {
  const std::vector<Eigen::Vector3d> points(6, Eigen::Vector3d::Zero());
  const std::vector<std::int32_t> rows = {0, 0, 1, 2, 3, 4};
  PlanarEmOptions o;
  o.min_rows = 5;
  EXPECT_TRUE(seenByEnoughRows({points, rows}, {0, 1, 2, 3, 4, 5}, o));
  EXPECT_FALSE(seenByEnoughRows({points, rows}, {0, 1, 2, 3, 4}, o));
  EXPECT_FALSE(seenByEnoughRows({points, rows}, {}, o));
  const std::vector<std::int32_t> none;
  EXPECT_TRUE(seenByEnoughRows({points, none}, {0}, o));  // no rows known
}

TEST(SelectionPolicy, Item14_CheckSurfaceNamesWhatFails) {
  std::mt19937_64 rng(3);
  testing::Cloud wall, bin;
  testing::addPlane(wall, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 3.0, 2.0, 0.05, 0.01, rng);
  testing::addCylinder(bin, {0, 0, 0.3}, 0.24, 0.8, 0.03, 0.02, rng, 0);
  const PlanarEmOptions o;
  const auto all_wall = allIndices(wall.points.size());
  const SurfaceVerdict ok = checkSurface({wall.points, wall.rows}, all_wall, fitted(wall), o, 60);
  EXPECT_TRUE(ok.valid());
  const SurfaceVerdict few =
      checkSurface({wall.points, wall.rows}, all_wall, fitted(wall), o, all_wall.size() + 1);
  EXPECT_FALSE(few.enough_points);
  EXPECT_FALSE(few.valid());
  const SurfaceVerdict curved =
      checkSurface({bin.points, bin.rows}, allIndices(bin.points.size()), fitted(bin), o, 60);
  EXPECT_TRUE(curved.curved);
  EXPECT_FALSE(curved.valid());
  Rectangle r;
  EXPECT_TRUE(fitValidSurface({wall.points, wall.rows}, all_wall, r, o, 60));
  EXPECT_FALSE(fitValidSurface({bin.points, bin.rows}, allIndices(bin.points.size()), r, o, 60));
}

// Surfaces are opaque: two surfaces over the same place within the split
// test's offset are one surface (fused whatever the likelihood says), while
// a door 10 cm behind its wall, or a surface beside another, is not.
TEST(SelectionPolicy, TwoSurfacesAtTheSamePlaceAreOne) {
  PlanarEmOptions o;  // split_min_offset_m 4 cm
  Rectangle wall;
  wall.normal = {1, 0, 0};
  wall.offset = 2.0;
  wall.centre = {2, 0, 1};
  wall.axis_u = {0, 1, 0};
  wall.half_u = 2.0;
  wall.half_v = 1.0;
  Rectangle copy = wall;  // 2 cm in front of it, over half of it
  copy.centre = {1.98, 1.0, 1};
  copy.offset = 1.98;
  copy.half_u = 1.0;
  EXPECT_TRUE(sameSurfacePlace(wall, copy, o.split_min_offset_m, o));
  EXPECT_TRUE(sameSurfacePlace(copy, wall, o.split_min_offset_m, o));
  Rectangle door = copy;  // 10 cm behind it, in its rectangle
  door.centre = {2.1, 1.0, 1};
  door.offset = 2.1;
  door.half_u = 0.45;
  EXPECT_FALSE(sameSurfacePlace(wall, door, o.split_min_offset_m, o));
  EXPECT_FALSE(sameSurfacePlace(wall, door, o.rules.same_place_clearance * o.split_min_offset_m,
                                o));  // may be created
  Rectangle beside = wall;            // the next wall along, no overlap
  beside.centre = {2, 4.5, 1};
  EXPECT_FALSE(sameSurfacePlace(wall, beside, o.split_min_offset_m, o));
  Rectangle across = wall;  // the same place, at right angles: a corner
  across.normal = {0, 1, 0};
  across.axis_u = {1, 0, 0};
  EXPECT_FALSE(sameSurfacePlace(wall, across, o.split_min_offset_m, o));
}

TEST(SelectionPolicy, Item14_EveryRuleIsValidated) {
  PlanarEmOptions o;
  std::string why;
  ASSERT_TRUE(o.validate(&why)) << why;
  const std::vector<std::function<void(SelectionRules&)>> bad = {
      [](SelectionRules& r) { r.grow_sigmas = 0; },
      [](SelectionRules& r) { r.recut_max_transfer_percent = 101; },
      [](SelectionRules& r) { r.removal_passes = 0; },
      [](SelectionRules& r) { r.tabu_angle_deg = 90; },
      [](SelectionRules& r) { r.poor_coverage_empty_fraction = 1.0; },
      [](SelectionRules& r) { r.min_part_points = 2; },
      [](SelectionRules& r) { r.coherent_neighbours = 5; },
      [](SelectionRules& r) { r.curved_min_variance_explained = 1.5; },
      [](SelectionRules& r) { r.residual_sigmas = 0; },
      [](SelectionRules& r) { r.corner_on_plane_percent = 101; },
      [](SelectionRules& r) { r.seed_attempts_per_surface = 0; },
      [](SelectionRules& r) { r.same_place_overlap_percent = 0; },
      [](SelectionRules& r) { r.same_place_clearance = 0.5; },
  };
  for (std::size_t k = 0; k < bad.size(); ++k) {
    PlanarEmOptions b;
    bad[k](b.rules);
    why.clear();
    EXPECT_FALSE(b.validate(&why)) << k;
    EXPECT_NE(why.find("rules."), std::string::npos) << k << ": " << why;
  }
}

}  // namespace
}  // namespace pmap::em
