#include "pmap/refine/seams.h"

#include <gtest/gtest.h>

#include "refine_world.h"

namespace pmap::refine {
namespace {

using testing::rectangle;

std::vector<SurfaceParams> paramsOf(const std::vector<em::Rectangle>& rects) {
  std::vector<SurfaceParams> p;
  for (const auto& r : rects)
    p.push_back(SurfaceParams::fromRectangle(r));
  return p;
}

const Eigen::Vector3d kX = Eigen::Vector3d::UnitX();

TEST(FindSeams, AWallUnderACeilingMeetsItAndViceVersa) {
  const auto scene = testing::wallUnderCeiling(0.0);
  // The wall's top edge 8 cm below the ceiling, the ceiling 6 cm short of the wall.
  const std::vector<em::Rectangle> rects = {scene.surfaces[0].rect, scene.surfaces[1].rect};
  const auto seams = findSeams(paramsOf(rects), RefineOptions{});
  ASSERT_EQ(seams.size(), 2u);
  EXPECT_EQ(seams[0].surface, 0u);
  EXPECT_EQ(seams[0].other, 1u);
  EXPECT_NEAR(seams[0].distance_m, 0.08, 1e-9);
  EXPECT_EQ(seams[1].surface, 1u);
  EXPECT_EQ(seams[1].other, 0u);
  EXPECT_NEAR(seams[1].distance_m, 0.06, 1e-9);
  // The seam is held along the part of the edge beside the other rectangle:
  // here all of it (4 m).
  EXPECT_NEAR(std::abs(seams[0].along[1] - seams[0].along[0]), 4.0, 1e-9);
}

TEST(FindSeams, ParallelNeighboursNeverMeet) {
  // A door recessed 10 cm behind its wall, side by side.
  const std::vector<em::Rectangle> rects = {
      rectangle(Eigen::Vector3d::UnitY(), {2, 0, 1.35}, kX, 2.0, 1.35),
      rectangle(Eigen::Vector3d::UnitY(), {4.5, 0.1, 1.0}, kX, 0.45, 1.0)};
  EXPECT_TRUE(findSeams(paramsOf(rects), RefineOptions{}).empty());
}

TEST(FindSeams, FarOrCrossingSurfacesAreNotSeams) {
  RefineOptions o;
  // A ceiling 50 cm above the wall's top edge: too far.
  const std::vector<em::Rectangle> far = {
      rectangle(Eigen::Vector3d::UnitY(), {2, 0, 1.1}, kX, 2.0, 1.1),
      rectangle(-Eigen::Vector3d::UnitZ(), {2, 1, 2.7}, kX, 2.0, 1.0)};
  EXPECT_TRUE(findSeams(paramsOf(far), o).empty());
  // A wall whose end edges are across the line of a wall 5 m away.
  const std::vector<em::Rectangle> apart = {
      rectangle(Eigen::Vector3d::UnitY(), {2, 0, 1.35}, kX, 2.0, 1.35),
      rectangle(Eigen::Vector3d::UnitX(), {9.0, 2.0, 1.35}, Eigen::Vector3d::UnitY(), 1.0, 1.35)};
  EXPECT_TRUE(findSeams(paramsOf(apart), o).empty());
}

TEST(FindSeams, AnEdgeUnderTwoCeilingPiecesEndsOnBoth) {
  const std::vector<em::Rectangle> rects = {
      rectangle(Eigen::Vector3d::UnitY(), {4, 0, 1.3}, kX, 4.0, 1.3),
      rectangle(-Eigen::Vector3d::UnitZ(), {1.5, 1, 2.7}, kX, 1.5, 1.0),
      rectangle(-Eigen::Vector3d::UnitZ(), {5.5, 1, 2.7}, kX, 2.5, 1.0)};
  const auto seams = findSeams(paramsOf(rects), RefineOptions{});
  int wall_seams = 0;
  for (const Seam& s : seams) {
    if (s.surface == 0) {
      ++wall_seams;
      // Held only beside its ceiling piece: 3 m and 5 m (+- the slack).
      const double length = std::abs(s.along[1] - s.along[0]);
      EXPECT_NEAR(length, s.other == 1 ? 3.0 : 5.0, 0.3 + 8.0 / 32);
    }
  }
  EXPECT_EQ(wall_seams, 2);
}

TEST(DistanceToIntersection, InPlaneDistanceForAnyAngle) {
  // Plane a: y = 0; plane b tilted 45 deg about x, through the line y = 0, z = 1.
  const Eigen::Vector3d na = Eigen::Vector3d::UnitY();
  const Eigen::Vector3d nb = Eigen::Vector3d(0, 1, 1).normalized();
  const double db = nb.dot(Eigen::Vector3d(0, 0, 1));
  EXPECT_NEAR(distanceToIntersection(na, nb, db, {3, 0, 0.8}), 0.2, 1e-12);
  EXPECT_TRUE(std::isinf(distanceToIntersection(na, na, 0.5, {0, 0, 0})));
}

}  // namespace
}  // namespace pmap::refine
