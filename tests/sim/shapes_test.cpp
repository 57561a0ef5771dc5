#include "pmap/sim/shapes.h"

#include <gtest/gtest.h>

namespace pmap::sim {
namespace {

using Eigen::Vector3d;

/// A 4 m x 3 m wall in the plane x = 2, facing -x, with a door hole.
Rectangle3 wallWithHole() {
  Rectangle3 r = Rectangle3::fromCorners(Vector3d(2, -2, 0), Vector3d(2, 2, 0), Vector3d(2, -2, 3));
  r.holes.push_back(HoleRange{1.5, 2.5, 0.0, 2.0});  // y in [-0.5, 0.5], z in [0, 2]
  return r;
}

TEST(RayRectangle, HitsInside) {
  const auto hit =
      intersectRectangle(wallWithHole(), Vector3d(0, 1.0, 1.0), Vector3d(1, 0, 0), 0.0, 100.0);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 2.0, 1e-12);
  EXPECT_NEAR(hit->local.x(), 3.0, 1e-12);
  EXPECT_NEAR(hit->local.y(), 1.0, 1e-12);
}

TEST(RayRectangle, MissesOutside) {
  EXPECT_FALSE(
      intersectRectangle(wallWithHole(), Vector3d(0, 2.5, 1.0), Vector3d(1, 0, 0), 0.0, 100.0));
  EXPECT_FALSE(
      intersectRectangle(wallWithHole(), Vector3d(0, 0.0, 3.5), Vector3d(1, 0, 0), 0.0, 100.0));
}

TEST(RayRectangle, PassesThroughHole) {
  EXPECT_FALSE(
      intersectRectangle(wallWithHole(), Vector3d(0, 0.0, 1.0), Vector3d(1, 0, 0), 0.0, 100.0));
  // Above the hole the wall is solid again.
  EXPECT_TRUE(
      intersectRectangle(wallWithHole(), Vector3d(0, 0.0, 2.5), Vector3d(1, 0, 0), 0.0, 100.0));
}

TEST(RayRectangle, GrazingAndParallelRaysMiss) {
  // In the plane itself and parallel to it.
  EXPECT_FALSE(
      intersectRectangle(wallWithHole(), Vector3d(2, -3, 1), Vector3d(0, 1, 0), 0.0, 100.0));
  EXPECT_FALSE(
      intersectRectangle(wallWithHole(), Vector3d(1, -3, 1), Vector3d(0, 1, 0), 0.0, 100.0));
}

TEST(RayRectangle, RespectsRangeAndDirection) {
  const Rectangle3 r = wallWithHole();
  EXPECT_FALSE(intersectRectangle(r, Vector3d(0, 1, 1), Vector3d(-1, 0, 0), 0.0, 100.0));
  EXPECT_FALSE(intersectRectangle(r, Vector3d(0, 1, 1), Vector3d(1, 0, 0), 0.0, 1.9));
  // Two-sided: hit from behind too.
  EXPECT_TRUE(intersectRectangle(r, Vector3d(4, 1, 1), Vector3d(-1, 0, 0), 0.0, 100.0));
}

TEST(RayRectangle, FacingOrientsTheNormalTowardsFreeSpace) {
  const Rectangle3 r = Rectangle3::facing(Vector3d(2, -2, 0), Vector3d(2, 2, 0), Vector3d(2, -2, 3),
                                          Vector3d(0, 0, 1));
  EXPECT_TRUE(r.normal().isApprox(Vector3d(-1, 0, 0)));
  const Rectangle3 s = Rectangle3::facing(Vector3d(2, -2, 0), Vector3d(2, 2, 0), Vector3d(2, -2, 3),
                                          Vector3d(5, 0, 1));
  EXPECT_TRUE(s.normal().isApprox(Vector3d(1, 0, 0)));
}

const VerticalCylinder kBin{Eigen::Vector2d(3.0, 0.0), 0.5, 0.0, 1.0};

TEST(RayCylinder, HitsTheSide) {
  const auto hit = intersectCylinder(kBin, Vector3d(0, 0, 0.5), Vector3d(1, 0, 0), 0.0, 100.0);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 2.5, 1e-12);
  EXPECT_TRUE(hit->normal.isApprox(Vector3d(-1, 0, 0)));
}

TEST(RayCylinder, Misses) {
  EXPECT_FALSE(intersectCylinder(kBin, Vector3d(0, 0.6, 0.5), Vector3d(1, 0, 0), 0.0, 100.0));
  EXPECT_FALSE(intersectCylinder(kBin, Vector3d(0, 0, 0.5), Vector3d(-1, 0, 0), 0.0, 100.0));
}

TEST(RayCylinder, FromInsideHitsTheExit) {
  const auto hit = intersectCylinder(kBin, Vector3d(3, 0, 0.5), Vector3d(0, 1, 0), 0.0, 100.0);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 0.5, 1e-12);
}

TEST(RayCylinder, AboveItsTopMissesUnlessItComesDown) {
  EXPECT_FALSE(intersectCylinder(kBin, Vector3d(0, 0, 1.2), Vector3d(1, 0, 0), 0.0, 100.0));
  // Coming down onto the top cap.
  const auto hit = intersectCylinder(kBin, Vector3d(3, 0, 2.0), Vector3d(0, 0, -1), 0.0, 100.0);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 1.0, 1e-12);
  EXPECT_TRUE(hit->normal.isApprox(Vector3d(0, 0, 1)));
}

TEST(RayBox, HitsNearestFaceAndFromInside) {
  const VerticalBox box{Eigen::Vector2d(3.0, 0.0), Eigen::Vector2d(0.5, 0.25), M_PI / 2, 0.0, 2.0};
  // Rotated by 90 deg: extends +-0.25 in x, +-0.5 in y.
  const auto hit = intersectBox(box, Vector3d(0, 0, 1), Vector3d(1, 0, 0), 0.0, 100.0);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 2.75, 1e-12);
  EXPECT_TRUE(hit->normal.isApprox(Vector3d(-1, 0, 0), 1e-12));
  const auto inside = intersectBox(box, Vector3d(3, 0, 1), Vector3d(0, 1, 0), 0.0, 100.0);
  ASSERT_TRUE(inside);
  EXPECT_NEAR(inside->t, 0.5, 1e-12);
  EXPECT_FALSE(intersectBox(box, Vector3d(0, 0.6, 1), Vector3d(1, 0, 0), 0.0, 100.0));
  EXPECT_FALSE(intersectBox(box, Vector3d(0, 0, 2.5), Vector3d(1, 0, 0), 0.0, 100.0));
}

}  // namespace
}  // namespace pmap::sim
