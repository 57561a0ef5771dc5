#include "pmap/eval/reference_surfaces.h"

#include <gtest/gtest.h>

#include "pmap/eval/point_labels.h"
#include "surface_test_world.h"

namespace pmap::eval {
namespace {
using testing::rectangle;
using testing::SurfaceTestWorld;

// A 10 m x 3 m wall in the plane y = 0, c0 at the origin, c3 above c0.
const Rectangle kWall = rectangle({0, 0, 0}, {10, 0, 0}, {0, 0, 3});

void expectCorners(const Rectangle& r, const Rectangle& expected) {
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR((r[k] - expected[k]).norm(), 0.0, 1e-12) << "corner " << k;
  }
}

TEST(ReferenceSurfaces, ClipsToTheBoundingBoxOfThePointsInTheRectanglesFrame) {
  const std::vector<Eigen::Vector3d> pts = {{2, 0.01, 0.5}, {6, -0.02, 2.0}, {4, 0, 1}};
  expectCorners(clipToPoints(kWall, pts), rectangle({2, 0, 0.5}, {4, 0, 0}, {0, 0, 1.5}));
}

TEST(ReferenceSurfaces, ClippingKeepsTheRectangleAndItsCornerOrder) {
  // Points beyond the rectangle (noise) are clipped to it; no points: unchanged.
  const std::vector<Eigen::Vector3d> pts = {{-0.5, 0, -0.1}, {11, 0, 3.2}};
  expectCorners(clipToPoints(kWall, pts), kWall);
  expectCorners(clipToPoints(kWall, {}), kWall);
  // A rectangle listed from another corner, other winding: same corner order out.
  const Rectangle other = {kWall[2], kWall[1], kWall[0], kWall[3]};
  const Rectangle c = clipToPoints(other, {{2, 0, 0.5}, {6, 0, 2.0}});
  expectCorners(c, {Eigen::Vector3d(6, 0, 2), {6, 0, 0.5}, {2, 0, 0.5}, {2, 0, 2}});
}

TEST(ReferenceSurfaces, EligibleSurfacesHaveEnoughHitsAndAreNeverClutter) {
  SurfaceTestWorld w;
  w.addRectangle(4, "wall", kWall);
  w.addRectangle(2, "door", rectangle({0, 5, 0}, {1, 0, 0}, {0, 0, 2}));
  w.addRectangle(9, "floor", rectangle({0, 0, 0}, {0, 5, 0}, {10, 0, 0}));
  w.addCylinder(20, {5, 2}, 0.2);
  w.addGrid(4, -1, 10, 10, 0.2, 0.6, 0.0, 0.5);  // 100 points on the wall
  w.addHitsWithoutPoints(4, 100);                // 200 hits in all
  w.addHitsWithoutPoints(2, 199);
  w.addHitsWithoutPoints(9, 50);
  w.addHitsWithoutPoints(20, 1000);
  const std::vector<int> labels = pointLabels(w.gt, w.points);
  const auto refs = referenceSurfaces(w.gt, countHits(w.gt), w.points.xyz, labels, 200);
  ASSERT_EQ(refs.size(), 1u);
  EXPECT_EQ(refs[0].rect.id, 4);
  EXPECT_EQ(refs[0].hits, 200u);
  EXPECT_EQ(refs[0].points, 100u);
  expectCorners(refs[0].clipped, rectangle({2, 0, 0}, {4, 0, 0}, {0, 0, 1.5}));
  EXPECT_EQ(referenceSurfaces(w.gt, countHits(w.gt), w.points.xyz, labels, 199).size(), 2u);
}

TEST(ReferenceSurfaces, SortedByIdAndUnclippedWithoutPoints) {
  SurfaceTestWorld w;
  w.addRectangle(8, "wall", kWall);
  w.addRectangle(3, "wall", rectangle({0, 4, 0}, {10, 0, 0}, {0, 0, 3}));
  w.addHitsWithoutPoints(8, 300);
  w.addHitsWithoutPoints(3, 300);
  const auto refs = referenceSurfaces(w.gt, countHits(w.gt), {}, {}, 200);
  ASSERT_EQ(refs.size(), 2u);
  EXPECT_EQ(refs[0].rect.id, 3);
  EXPECT_EQ(refs[1].rect.id, 8);
  EXPECT_EQ(refs[1].points, 0u);
  expectCorners(refs[1].clipped, kWall);
}

}  // namespace
}  // namespace pmap::eval
