#include "pmap/eval/surface_evaluation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pmap/common/error.h"
#include "surface_test_world.h"

namespace pmap::eval {
namespace {
using testing::rectangle;
using testing::surfaceFromCorners;
using testing::SurfaceTestWorld;

/// A corridor 20 m long, 2 m wide, 3 m high: two walls, floor, ceiling (each
/// seen by 240 beams), a small jamb seen by 9 (not eligible), a bin (id 10).
SurfaceTestWorld corridor() {
  SurfaceTestWorld w;
  w.addRectangle(0, "wall", rectangle({0, 0, 0}, {20, 0, 0}, {0, 0, 3}));
  w.addRectangle(1, "wall", rectangle({20, 2, 0}, {-20, 0, 0}, {0, 0, 3}));
  w.addRectangle(2, "floor", rectangle({0, 0, 0}, {0, 2, 0}, {20, 0, 0}));
  w.addRectangle(3, "ceiling", rectangle({0, 0, 3}, {20, 0, 0}, {0, 2, 0}));
  w.addRectangle(4, "jamb", rectangle({5, 0, 0}, {0, -0.1, 0}, {0, 0, 2}));
  w.addCylinder(10, {10, 1}, 0.2);
  for (int id = 0; id < 4; ++id) {
    w.addGrid(id, id, 20, 12);
  }
  w.addGrid(4, 4, 3, 3);
  for (int i = 0; i < 30; ++i) {
    w.addPoint({10, 1.2, 0.1 * i}, 10, -1);
  }
  return w;
}

/// The perfect map of the corridor: one map surface per ground-truth surface.
std::vector<MapSurface> perfectMap(const SurfaceTestWorld& w) {
  std::vector<MapSurface> s;
  for (int id = 0; id < 5; ++id) {
    s.push_back(w.perfectSurface(id, id));
  }
  return s;
}

void expectPerfect(const SurfaceEvaluation& e) {
  EXPECT_EQ(e.surfaces, 5u);
  EXPECT_EQ(e.gt_surfaces, 4u);
  EXPECT_EQ(e.matched_surfaces, 4u);
  EXPECT_EQ(e.map_surfaces_unmatched, 0u);
  EXPECT_TRUE(e.unmatched.empty());
  EXPECT_NEAR(*e.normal_error_deg.mean(), 0.0, 1e-6);
  EXPECT_NEAR(e.offset_error_m.max, 0.0, 1e-9);
  EXPECT_NEAR(e.corner_error_m.max, 0.0, 1e-9);
  EXPECT_NEAR(*e.labels.recall, 1.0, 1e-12);
  EXPECT_NEAR(*e.labels.precision, 1.0, 1e-12);
  EXPECT_NEAR(*e.labels.f1, 1.0, 1e-12);
  EXPECT_EQ(e.labels.clutter_points, 30u);
  EXPECT_NEAR(*e.labels.clutter_rejected_fraction, 1.0, 1e-12);
}

TEST(SurfaceEvaluation, PerfectMapScoresPerfectly) {
  SurfaceTestWorld w = corridor();
  const SurfaceEvaluation e = evaluateSurfaces(w.gt, w.points, perfectMap(w), Rigid2D{});
  expectPerfect(e);
  EXPECT_EQ(e.matched_by_kind.at("wall").gt, 2u);
  EXPECT_EQ(e.matched_by_kind.at("wall").matched, 2u);
  EXPECT_EQ(e.matched_by_kind.at("ceiling").matched, 1u);
  EXPECT_EQ(e.matched_by_kind.count("jamb"), 0u);  // not eligible
  ASSERT_EQ(e.per_surface.size(), 4u);
  EXPECT_EQ(e.per_surface[3].gt_id, 3);
  EXPECT_EQ(e.per_surface[3].map_id, 3);
  EXPECT_EQ(e.per_surface[3].points, 240u);
  EXPECT_EQ(e.per_surface[3].hits, 240u);
  EXPECT_EQ(e.per_surface[3].map_surfaces_matching, 1u);
}

TEST(SurfaceEvaluation, PerfectMapInAnotherFrameIsAlignedFirst) {
  SurfaceTestWorld w = corridor();
  const Rigid2D map_to_gt{0.8, {3.0, -7.0}};
  const Rigid2D gt_to_map{-0.8, -Rigid2D{-0.8, {0, 0}}.apply({3.0, -7.0, 0}).head<2>()};
  std::vector<MapSurface> map;
  for (const auto& s : perfectMap(w)) {
    map.push_back(movedSurface(s, gt_to_map));
  }
  for (auto& p : w.points.xyz) {
    p = gt_to_map.apply(p);
  }
  expectPerfect(evaluateSurfaces(w.gt, w.points, map, map_to_gt));
  EXPECT_GT(evaluateSurfaces(w.gt, w.points, map, Rigid2D{}).corner_error_m.max, 1.0);
}

// A wall 10 m x 3 m in the plane y = 0; its map surface rotated by 2 degrees
// about the vertical through the wall's centre c and moved 5 cm along the
// normal n = (0, -1, 0). By hand, corner p maps to c + R (p - c) + 0.05 n:
//  normal error 2 deg; offset error = |n' . c - offset| = 0.05 cos 2deg;
//  corners at x = 10: |(5 (cos 2deg - 1), 5 sin 2deg - 0.05)| = 0.1245347,
//  corners at x = 0:  |(5 (1 - cos 2deg), -5 sin 2deg - 0.05)| = 0.2245181,
//  corner error = their mean = 0.1745264.
TEST(SurfaceEvaluation, RotatedAndOffsetSurfaceErrorsByHand) {
  SurfaceTestWorld w;
  w.addRectangle(1, "wall", rectangle({0, 0, 0}, {10, 0, 0}, {0, 0, 3}));
  w.addGrid(1, 7, 20, 12);
  const GtRectangle& r = *w.gt.surface(1);
  ASSERT_EQ(r.normal, Eigen::Vector3d(0, -1, 0));
  const Eigen::Vector3d c(5, 0, 1.5);
  const Rigid2D rotate{2.0 * M_PI / 180.0, {0, 0}};
  Rectangle corners;
  for (std::size_t k = 0; k < 4; ++k) {
    corners[k] = c + rotate.apply(r.corners[k] - c) + 0.05 * r.normal;
  }
  // Reversed order: the correspondence must not depend on it.
  const MapSurface s = surfaceFromCorners(7, {corners[3], corners[2], corners[1], corners[0]});
  const SurfaceEvaluation e = evaluateSurfaces(w.gt, w.points, {s}, Rigid2D{});
  ASSERT_EQ(e.matched_surfaces, 1u);
  const SurfaceScore& score = e.per_surface[0];
  EXPECT_NEAR(score.normal_error_deg, 2.0, 1e-9);
  EXPECT_NEAR(score.offset_error_m, 0.05 * std::cos(2.0 * M_PI / 180.0), 1e-12);
  EXPECT_NEAR(score.offset_error_m, 0.0499695, 1e-7);
  EXPECT_NEAR(score.corner_error_m, 0.1745264, 1e-7);
  EXPECT_NEAR(*e.corner_error_m.mean(), 0.1745264, 1e-7);
  EXPECT_NEAR(e.corner_error_m.max, 0.1745264, 1e-7);
}

TEST(SurfaceEvaluation, CornersAreComparedWithWhatTheLaserSaw) {
  SurfaceTestWorld w;
  w.addRectangle(1, "wall", rectangle({0, 0, 0}, {10, 0, 0}, {0, 0, 3}));
  w.addGrid(1, 7, 20, 12, 0.2, 0.6, 0.0, 1.0);  // x in [2, 6]
  MapSurface whole = w.perfectSurface(1, 7);
  const SurfaceEvaluation e = evaluateSurfaces(w.gt, w.points, {whole}, Rigid2D{});
  // (2 + 4 + 4 + 2) / 4: the map extends 2 m and 4 m beyond the seen part.
  EXPECT_NEAR(e.per_surface[0].corner_error_m, 3.0, 1e-12);
  EXPECT_NEAR(e.per_surface[0].offset_error_m, 0.0, 1e-12);
  const MapSurface seen = surfaceFromCorners(7, rectangle({2, 0, 0}, {4, 0, 0}, {0, 0, 3}));
  EXPECT_NEAR(evaluateSurfaces(w.gt, w.points, {seen}, Rigid2D{}).corner_error_m.max, 0.0, 1e-12);
}

TEST(SurfaceEvaluation, SplitWallIsOneMatchedSurfaceWithTwoMapSurfaces) {
  SurfaceTestWorld w;
  w.addRectangle(1, "wall", rectangle({0, 0, 0}, {10, 0, 0}, {0, 0, 3}));
  w.addGrid(1, 5, 8, 30, 0.0, 0.4);   // 240 points, x in [0, 4]
  w.addGrid(1, 6, 12, 30, 0.5, 1.0);  // 360 points, x in [5, 10]: primary
  const std::vector<MapSurface> map = {
      surfaceFromCorners(5, rectangle({0, 0, 0}, {4, 0, 0}, {0, 0, 3})),
      surfaceFromCorners(6, rectangle({5, 0, 0}, {5, 0, 0}, {0, 0, 3}))};
  const SurfaceEvaluation e = evaluateSurfaces(w.gt, w.points, map, Rigid2D{});
  EXPECT_EQ(e.gt_surfaces, 1u);
  EXPECT_EQ(e.matched_surfaces, 1u);
  EXPECT_EQ(e.surfaces, 2u);
  EXPECT_EQ(e.map_surfaces_unmatched, 0u);
  ASSERT_EQ(e.per_surface.size(), 1u);
  EXPECT_EQ(e.per_surface[0].map_id, 6);
  EXPECT_EQ(e.per_surface[0].map_surfaces_matching, 2u);
  EXPECT_EQ(e.per_surface[0].points, 360u);
  EXPECT_NEAR(e.per_surface[0].corner_error_m, 2.5, 1e-12);  // (5 + 0 + 0 + 5) / 4
  EXPECT_NEAR(*e.labels.recall, 1.0, 1e-12);                 // both halves match the wall
}

// A wall mapped twice, as two parallel surfaces 0.15 m apart (one with its
// normal flipped): the spread of the matching planes is their distance; a
// split wall in one plane has none.
TEST(SurfaceEvaluation, ParallelDuplicatesShowTheirSpread) {
  SurfaceTestWorld w;
  w.addRectangle(1, "wall", rectangle({0, 0, 0}, {10, 0, 0}, {0, 0, 3}));
  w.addGrid(1, 5, 8, 30, 0.0, 0.4);
  w.addGrid(1, 6, 12, 30, 0.5, 1.0);
  const MapSurface in_plane = surfaceFromCorners(5, rectangle({0, 0, 0}, {4, 0, 0}, {0, 0, 3}));
  const MapSurface behind = surfaceFromCorners(6, rectangle({5, 0.15, 0}, {5, 0, 0}, {0, 0, 3}));
  const MapSurface flipped = surfaceFromCorners(6, rectangle({10, 0.15, 0}, {-5, 0, 0}, {0, 0, 3}));
  EXPECT_NEAR(evaluateSurfaces(w.gt, w.points, {in_plane, behind}, Rigid2D{})
                  .per_surface[0]
                  .matching_spread_m,
              0.15, 1e-9);
  EXPECT_NEAR(evaluateSurfaces(w.gt, w.points, {in_plane, flipped}, Rigid2D{})
                  .per_surface[0]
                  .matching_spread_m,
              0.15, 1e-9);
  const MapSurface split = surfaceFromCorners(6, rectangle({5, 0, 0}, {5, 0, 0}, {0, 0, 3}));
  EXPECT_NEAR(evaluateSurfaces(w.gt, w.points, {in_plane, split}, Rigid2D{})
                  .per_surface[0]
                  .matching_spread_m,
              0.0, 1e-12);
}

TEST(SurfaceEvaluation, UnmatchedSurfacesAreListedWithTheirHits) {
  SurfaceTestWorld w = corridor();
  std::vector<MapSurface> map = perfectMap(w);
  for (std::size_t i = 0; i < w.points.surface.size(); ++i) {
    if (w.points.surface[i] == 1) {
      w.points.surface[i] = -1;  // wall 1 not mapped
    }
  }
  map[2].normal = Eigen::Vector3d(1, 0, 0);  // the floor's map surface is vertical
  const SurfaceEvaluation e = evaluateSurfaces(w.gt, w.points, map, Rigid2D{});
  EXPECT_EQ(e.matched_surfaces, 2u);
  EXPECT_EQ(e.map_surfaces_unmatched, 2u);  // 1 (no points) and 2 (wrong normal)
  ASSERT_EQ(e.unmatched.size(), 2u);
  EXPECT_EQ(e.unmatched[0].id, 1);
  EXPECT_EQ(e.unmatched[0].kind, "wall");
  EXPECT_EQ(e.unmatched[0].hits, 240u);
  EXPECT_EQ(e.unmatched[1].kind, "floor");
  EXPECT_EQ(e.matched_by_kind.at("wall").gt, 2u);
  EXPECT_EQ(e.matched_by_kind.at("wall").matched, 1u);
  EXPECT_EQ(e.matched_by_kind.at("floor").matched, 0u);
  EXPECT_NEAR(*e.labels.recall, 480.0 / 960.0, 1e-12);
  EXPECT_NEAR(*e.labels.precision, (480.0 + 9.0) / (720.0 + 9.0), 1e-12);
}

TEST(SurfaceEvaluation, EmptyMapAndInvalidOptions) {
  SurfaceTestWorld w = corridor();
  for (auto& s : w.points.surface) {
    s = -1;
  }
  const SurfaceEvaluation e = evaluateSurfaces(w.gt, w.points, {}, Rigid2D{});
  EXPECT_EQ(e.gt_surfaces, 4u);
  EXPECT_EQ(e.matched_surfaces, 0u);
  EXPECT_FALSE(e.corner_error_m.mean().has_value());
  EXPECT_NEAR(*e.labels.recall, 0.0, 1e-12);
  EXPECT_FALSE(e.labels.precision.has_value());
  SurfaceEvalOptions bad;
  bad.min_hits = 0;
  EXPECT_THROW(evaluateSurfaces(w.gt, w.points, {}, Rigid2D{}, bad), ConfigError);
}

}  // namespace
}  // namespace pmap::eval
