#include "pmap/eval/surface_matching.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pmap/eval/point_labels.h"
#include "surface_test_world.h"

namespace pmap::eval {
namespace {
using testing::rectangle;
using testing::SurfaceTestWorld;

/// Two walls side by side in the plane y = 0 (ids 1 and 2) and a floor (3).
SurfaceTestWorld twoWalls() {
  SurfaceTestWorld w;
  w.addRectangle(1, "wall", rectangle({0, 0, 0}, {5, 0, 0}, {0, 0, 3}));
  w.addRectangle(2, "wall", rectangle({5, 0, 0}, {5, 0, 0}, {0, 0, 3}));
  w.addRectangle(3, "floor", rectangle({0, 0, 0}, {0, 5, 0}, {10, 0, 0}));
  return w;
}

SurfaceMatches match(const SurfaceTestWorld& w, const SurfaceMatchOptions& options = {}) {
  return matchSurfaces(w.gt, w.surfaces, w.points.surface, pointLabels(w.gt, w.points), options);
}

/// A map surface with the given normal through the origin (rectangle unused).
MapSurface surfaceWithNormal(int id, const Eigen::Vector3d& n) {
  MapSurface s;
  s.id = id;
  s.normal = n.normalized();
  return s;
}

TEST(SurfaceMatching, StraddlingSurfaceMatchesItsMajority) {
  SurfaceTestWorld w = twoWalls();
  w.addGrid(1, 10, 6, 10);  // 60 points of map surface 10 on wall 1
  w.addGrid(2, 10, 4, 10);  // 40 on wall 2
  w.surfaces = {surfaceWithNormal(10, {0, -1, 0})};
  const SurfaceMatches m = match(w);
  ASSERT_EQ(m.map_surfaces.size(), 1u);
  EXPECT_EQ(m.map_surfaces[0].points, 100u);
  EXPECT_EQ(m.map_surfaces[0].majority_label, 1);
  EXPECT_EQ(m.map_surfaces[0].majority_points, 60u);
  EXPECT_EQ(m.map_surfaces[0].gt_id, 1);
  EXPECT_EQ(m.matchedGt(10), 1);
  EXPECT_EQ(m.by_gt.count(2), 0u);
}

TEST(SurfaceMatching, SplitWallGivesOneGroundTruthSurfaceTwoMatchesLargestFirst) {
  SurfaceTestWorld w = twoWalls();
  w.addGrid(1, 7, 4, 10, 0.0, 0.4);
  w.addGrid(1, 5, 6, 10, 0.5, 1.0);
  w.surfaces = {surfaceWithNormal(7, {0, 1, 0}), surfaceWithNormal(5, {0, -1, 0})};
  const SurfaceMatches m = match(w);
  ASSERT_EQ(m.by_gt.size(), 1u);
  ASSERT_EQ(m.by_gt.at(1).size(), 2u);
  EXPECT_EQ(m.map_surfaces[m.by_gt.at(1)[0]].map_id, 5);  // 60 points: primary
  EXPECT_EQ(m.map_surfaces[m.by_gt.at(1)[1]].map_id, 7);
  EXPECT_EQ(m.matchedGt(7), 1);
  EXPECT_EQ(m.matchedGt(5), 1);
}

TEST(SurfaceMatching, NormalsFifteenDegreesApartDoNotMatch) {
  SurfaceTestWorld w = twoWalls();
  w.addGrid(1, 10, 10, 10);
  w.addGrid(2, 11, 10, 10);
  const double a15 = 15.0 * M_PI / 180.0;
  const double a9 = 9.0 * M_PI / 180.0;
  w.surfaces = {surfaceWithNormal(10, {std::sin(a15), -std::cos(a15), 0}),
                surfaceWithNormal(11, {0, std::cos(a9), std::sin(a9)})};
  const SurfaceMatches m = match(w);
  EXPECT_NEAR(m.map_surfaces[0].normal_angle_deg, 15.0, 1e-9);
  EXPECT_EQ(m.map_surfaces[0].gt_id, -1);
  EXPECT_EQ(m.matchedGt(10), -1);
  EXPECT_NEAR(m.map_surfaces[1].normal_angle_deg, 9.0, 1e-9);
  EXPECT_EQ(m.map_surfaces[1].gt_id, 2);
  SurfaceMatchOptions strict;
  strict.max_normal_angle_deg = 5.0;
  EXPECT_EQ(match(w, strict).matchedGt(11), -1);
}

TEST(SurfaceMatching, BelowHalfOrMostlyNothingOrClutterDoesNotMatch) {
  SurfaceTestWorld w = twoWalls();
  w.addCylinder(30, {5, 2}, 0.2);
  w.addGrid(1, 10, 4, 10);  // 40 % wall 1
  w.addGrid(2, 10, 3, 10);  // 30 % wall 2
  for (int i = 0; i < 30; ++i) {
    w.addPoint({5, 2.2, 0.5}, 30, 10);  // 30 % clutter
  }
  for (int i = 0; i < 20; ++i) {
    w.addPoint({1, 0, 1}, 1, 11);  // 20 points on wall 1 ...
    w.addPoint({1, 0, 9}, -1, 11);
    w.addPoint({1, 0, 9}, -1, 11);  // ... 40 whose true ray hit nothing
  }
  w.surfaces = {surfaceWithNormal(10, {0, 1, 0}), surfaceWithNormal(11, {0, 1, 0}),
                surfaceWithNormal(12, {0, 1, 0})};  // 12: no points
  const SurfaceMatches m = match(w);
  EXPECT_EQ(m.map_surfaces[0].majority_label, 1);
  EXPECT_EQ(m.map_surfaces[0].gt_id, -1);
  EXPECT_EQ(m.map_surfaces[1].points, 60u);
  EXPECT_EQ(m.map_surfaces[1].gt_id, -1);
  EXPECT_EQ(m.map_surfaces[2].points, 0u);
  EXPECT_EQ(m.map_surfaces[2].gt_id, -1);
  EXPECT_TRUE(m.by_gt.empty());
  EXPECT_TRUE(m.gt_of_map.empty());
}

TEST(SurfaceMatching, PointsWithoutLabelEntryAreIgnoredAndTiesGoToTheLowerId) {
  SurfaceTestWorld w = twoWalls();
  w.addGrid(2, 10, 5, 10);
  w.addGrid(1, 10, 5, 10);  // exactly 50/50
  w.points.xyz.emplace_back(0, 0, 0);
  w.points.scan.push_back(99);  // no such scan in the ground truth
  w.points.beam.push_back(0);
  w.points.surface.push_back(10);
  w.surfaces = {surfaceWithNormal(10, {0, 1, 0})};
  const SurfaceMatches m = match(w);
  EXPECT_EQ(m.map_surfaces[0].points, 100u);
  EXPECT_EQ(m.map_surfaces[0].gt_id, 1);
}

TEST(SurfaceMatching, OptionsAreValidated) {
  const auto rule = [](double share, double angle) {
    SurfaceMatchOptions o;
    o.min_label_share = share;
    o.max_normal_angle_deg = angle;
    return o.validate();
  };
  EXPECT_TRUE(SurfaceMatchOptions{}.validate().empty());
  EXPECT_TRUE(rule(1.0, 0.0).empty());
  EXPECT_NE(rule(0.4, 10.0).find("min_label_share"), std::string::npos);
  EXPECT_NE(rule(0.5, -1.0).find("max_normal_angle_deg"), std::string::npos);
  EXPECT_NE(rule(std::nan(""), 10.0).find("min_label_share"), std::string::npos);
}

}  // namespace
}  // namespace pmap::eval
