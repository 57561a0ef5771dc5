#include "pmap/eval/label_metrics.h"

#include <gtest/gtest.h>

#include "pmap/eval/point_labels.h"
#include "surface_test_world.h"

namespace pmap::eval {
namespace {
using testing::rectangle;
using testing::SurfaceTestWorld;

MapSurface surfaceWithNormal(int id, const Eigen::Vector3d& n) {
  MapSurface s;
  s.id = id;
  s.normal = n;
  return s;
}

LabelMetrics metrics(const SurfaceTestWorld& w, const std::unordered_set<int>& eligible) {
  const std::vector<int> labels = pointLabels(w.gt, w.points);
  const SurfaceMatches m = matchSurfaces(w.gt, w.surfaces, w.points.surface, labels, {});
  return labelMetrics(w.gt, w.points.surface, labels, m, eligible);
}

TEST(LabelMetrics, RecallPrecisionAndF1ByHand) {
  SurfaceTestWorld w;
  w.addRectangle(1, "wall", rectangle({0, 0, 0}, {5, 0, 0}, {0, 0, 3}));
  w.addRectangle(2, "wall", rectangle({5, 0, 0}, {5, 0, 0}, {0, 0, 3}));
  w.addRectangle(3, "jamb", rectangle({0, 0, 0}, {0, 0.1, 0}, {0, 0, 2}));  // not eligible
  w.addGrid(1, 10, 8, 10);        // 80 wall-1 points on map surface 10 (matches 1)
  w.addGrid(1, -1, 2, 10);        // 20 wall-1 points in the outlier class
  w.addGrid(2, 10, 2, 10);        // 20 wall-2 points wrongly on map surface 10
  w.addGrid(2, 11, 5, 10);        // 50 wall-2 points on map surface 11 (matches 2)
  w.addGrid(3, 12, 2, 5);         // 10 jamb points on map surface 12 (matches 3)
  w.addPoint({9, 9, 9}, -1, 11);  // a point whose true ray hit nothing, assigned
  w.surfaces = {surfaceWithNormal(10, {0, 1, 0}), surfaceWithNormal(11, {0, 1, 0}),
                surfaceWithNormal(12, {1, 0, 0})};
  const LabelMetrics m = metrics(w, {1, 2});
  EXPECT_EQ(m.on_surface_points, 170u);
  EXPECT_EQ(m.recalled_points, 130u);
  EXPECT_EQ(m.assigned_points, 161u);
  EXPECT_EQ(m.correct_points, 140u);  // the jamb's points are correct: 12 matches 3
  EXPECT_NEAR(*m.recall, 130.0 / 170.0, 1e-12);
  EXPECT_NEAR(*m.precision, 140.0 / 161.0, 1e-12);
  const double r = 130.0 / 170.0;
  const double p = 140.0 / 161.0;
  EXPECT_NEAR(*m.f1, 2 * p * r / (p + r), 1e-12);
  EXPECT_EQ(m.clutter_points, 0u);
  EXPECT_FALSE(m.clutter_rejected_fraction.has_value());
}

TEST(LabelMetrics, ClutterRejectionCounts) {
  SurfaceTestWorld w;
  w.addRectangle(1, "wall", rectangle({0, 0, 0}, {5, 0, 0}, {0, 0, 3}));
  w.addCylinder(40, {1, 1}, 0.2);
  w.gt.boxes.push_back(GtBox{});
  w.gt.boxes.back().id = 41;
  w.addGrid(1, 10, 10, 10);
  for (int i = 0; i < 7; ++i) {
    w.addPoint({1, 1.2, 0.5}, 40, -1);  // rejected
  }
  w.addPoint({1, 1.2, 0.5}, 40, 10);  // absorbed by the wall's map surface
  w.addPoint({3, 3, 0.5}, 41, -1);    // rejected
  w.addPoint({3, 3, 0.5}, 41, 10);    // absorbed
  w.surfaces = {surfaceWithNormal(10, {0, 1, 0})};
  const LabelMetrics m = metrics(w, {1});
  EXPECT_EQ(m.clutter_points, 10u);
  EXPECT_EQ(m.clutter_rejected, 8u);
  EXPECT_NEAR(*m.clutter_rejected_fraction, 0.8, 1e-12);
  EXPECT_NEAR(*m.recall, 1.0, 1e-12);
  EXPECT_NEAR(*m.precision, 100.0 / 102.0, 1e-12);
}

// A person walking through is clutter that moves: its points belong on no surface.
TEST(LabelMetrics, Issue16_PeopleCountAsClutter) {
  SurfaceTestWorld w;
  w.addRectangle(1, "wall", rectangle({0, 0, 0}, {5, 0, 0}, {0, 0, 3}));
  w.gt.people = {50};
  w.addGrid(1, 10, 10, 10);
  for (int i = 0; i < 3; ++i) {
    w.addPoint({1, 1.2, 0.5}, 50, -1);  // rejected
  }
  w.addPoint({1, 1.2, 0.5}, 50, 10);  // absorbed by the wall's map surface
  w.addCylinder(40, {1, 1}, 0.2);
  w.addPoint({1, 1.2, 0.5}, 40, -1);
  w.addPoint({9, 9, 9}, -1, -1);  // a spurious return
  w.addPoint({9, 9, 9}, -1, 10);
  w.surfaces = {surfaceWithNormal(10, {0, 1, 0})};
  const LabelMetrics m = metrics(w, {1});
  EXPECT_EQ(m.clutter_points, 5u);
  EXPECT_EQ(m.clutter_rejected, 4u);
  EXPECT_NEAR(*m.precision, 100.0 / 102.0, 1e-12);
  // Where the points are, by what their true ray hit.
  ASSERT_EQ(m.by_truth.size(), 4u);
  EXPECT_EQ(m.by_truth.at("rectangle").points, 100u);
  EXPECT_EQ(m.by_truth.at("rectangle").on_map_surface, 100u);
  EXPECT_EQ(m.by_truth.at("person").points, 4u);
  EXPECT_EQ(m.by_truth.at("person").on_map_surface, 1u);
  EXPECT_EQ(m.by_truth.at("cylinder").points, 1u);
  EXPECT_EQ(m.by_truth.at("cylinder").on_map_surface, 0u);
  EXPECT_EQ(m.by_truth.at("no_object").points, 2u);
  EXPECT_EQ(m.by_truth.at("no_object").on_map_surface, 1u);
}

TEST(LabelMetrics, NothingAssignedLeavesPrecisionUndefined) {
  SurfaceTestWorld w;
  w.addRectangle(1, "wall", rectangle({0, 0, 0}, {5, 0, 0}, {0, 0, 3}));
  w.addGrid(1, -1, 3, 3);
  const LabelMetrics m = metrics(w, {1});
  EXPECT_EQ(m.on_surface_points, 9u);
  EXPECT_NEAR(*m.recall, 0.0, 1e-12);
  EXPECT_FALSE(m.precision.has_value());
  EXPECT_FALSE(m.f1.has_value());
  const LabelMetrics empty = metrics(SurfaceTestWorld{}, {});
  EXPECT_FALSE(empty.recall.has_value());
  EXPECT_FALSE(empty.precision.has_value());
}

}  // namespace
}  // namespace pmap::eval
