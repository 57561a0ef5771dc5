#include "pmap/sim/ray_caster.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace pmap::sim {
namespace {

using Eigen::Vector3d;

World twoWallsAndABin() {
  World w;
  for (const double x : {2.0, 5.0}) {
    Surface s;
    s.id = static_cast<int>(w.surfaces.size());
    s.kind = "wall";
    s.rect = Rectangle3::fromCorners(Vector3d(x, -2, 0), Vector3d(x, 2, 0), Vector3d(x, -2, 3));
    w.surfaces.push_back(s);
  }
  Clutter bin;
  bin.id = 2;
  bin.kind = "bin";
  bin.cylinder = VerticalCylinder{Eigen::Vector2d(1.0, 1.0), 0.2, 0.0, 1.0};
  w.clutter.push_back(bin);
  return w;
}

TEST(RayCaster, ClosestHitWins) {
  const World w = twoWallsAndABin();
  const RayCaster caster(w);
  const auto hit = caster.cast(Vector3d(0, 0, 1), Vector3d(1, 0, 0), 30.0);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->id, 0);
  EXPECT_NEAR(hit->t, 2.0, 1e-12);
  const auto from_between = caster.cast(Vector3d(3, 0, 1), Vector3d(1, 0, 0), 30.0);
  ASSERT_TRUE(from_between);
  EXPECT_EQ(from_between->id, 1);
  const auto bin = caster.cast(Vector3d(0, 1, 0.5), Vector3d(1, 0, 0), 30.0);
  ASSERT_TRUE(bin);
  EXPECT_EQ(bin->id, 2);
  EXPECT_EQ(bin->type, ObjectType::kClutter);
  EXPECT_NEAR(bin->t, 0.8, 1e-12);
}

TEST(RayCaster, MaxRangeLimitsHits) {
  const World w = twoWallsAndABin();
  const RayCaster caster(w);
  EXPECT_FALSE(caster.cast(Vector3d(0, 0, 1), Vector3d(1, 0, 0), 1.5));
  EXPECT_FALSE(caster.cast(Vector3d(0, 0, 1), Vector3d(-1, 0, 0), 30.0));
}

TEST(RayCaster, CandidateSelectionAgreesWithFullCast) {
  const World w = twoWallsAndABin();
  const RayCaster caster(w);
  const Vector3d origin(0, 0, 1);
  const std::vector<int> near_plane = caster.selectNearPlane(origin, Vector3d(0, 0, 1), 30.0);
  for (int i = 0; i < 36; ++i) {
    const double a = i * M_PI / 18.0;
    const Vector3d dir(std::cos(a), std::sin(a), 0.0);
    const auto full = caster.cast(origin, dir, 30.0);
    const auto culled = caster.cast(origin, dir, 30.0, &near_plane);
    ASSERT_EQ(full.has_value(), culled.has_value());
    if (full) {
      EXPECT_EQ(full->id, culled->id);
      EXPECT_EQ(full->t, culled->t);
    }
  }
  // The bin (z in [0, 1]) does not meet the plane z = 1.5.
  EXPECT_EQ(caster.selectNearPlane(Vector3d(0, 0, 2.5), Vector3d(0, 0, 1), 30.0).size(), 2u);
  const std::vector<int> near_bin = caster.selectNearPoint(Vector3d(1, 1, 0.5), 0.1);
  EXPECT_NE(std::find(near_bin.begin(), near_bin.end(), 2), near_bin.end());
  EXPECT_TRUE(caster.selectNearPoint(Vector3d(-5, 0, 1), 1.0).empty());
}

}  // namespace
}  // namespace pmap::sim
