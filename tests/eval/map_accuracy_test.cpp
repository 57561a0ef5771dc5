// The shared accuracy measure: a map equal to the ground truth has ~0 error,
// an offset map has error = offset both ways, samples stay where the laser
// saw, weighted statistics.
#include "pmap/eval/map_accuracy.h"

#include <gtest/gtest.h>

#include "surface_test_world.h"

namespace pmap::eval {
namespace {
using Eigen::Vector3d;
using testing::rectangle;
using testing::SurfaceTestWorld;

/// A 4 x 2.5 m wall (id 1) in the plane y = 1 with a grid of labelled points
/// on its left half only.
SurfaceTestWorld halfSeenWall() {
  SurfaceTestWorld w;
  w.addRectangle(1, "wall", rectangle({0, 1, 0}, {4, 0, 0}, {0, 0, 2.5}));
  w.addGrid(1, -1, 41, 26, 0.0, 0.5, 0.0, 1.0);
  return w;
}

std::vector<Triangle3> wallTriangles(double dy) {
  const Vector3d c0(0, 1 + dy, 0), u(4, 0, 0), v(0, 0, 2.5);
  return {{c0, c0 + u, c0 + u + v}, {c0, c0 + u + v, c0 + v}};
}

TEST(ErrorStats, WeightedMeanAndPercentile) {
  const ErrorStats s = errorStats({1, 2, 3, 10}, {1, 1, 1, 0.1});
  EXPECT_EQ(s.samples, 4u);
  EXPECT_NEAR(s.mean_m, (1 + 2 + 3 + 1.0) / 3.1, 1e-12);
  EXPECT_DOUBLE_EQ(s.p95_m, 3);  // 3.0 of 3.1 (96.8 %) is at or below 3
  EXPECT_EQ(errorStats({}, {}).samples, 0u);
  EXPECT_DOUBLE_EQ(errorStats({}, {}).mean_m, 0);
}

TEST(GroundTruthSamples, OnTheSurfaceWhereTheLaserSawIt) {
  const SurfaceTestWorld w = halfSeenWall();
  AccuracyOptions o;
  o.sample_spacing_m = 0.1;
  const auto samples = groundTruthSamples(w.gt, w.points, Rigid2D{}, o);
  ASSERT_GT(samples.size(), 100u);
  EXPECT_LT(samples.size(), w.points.xyz.size() + 1);
  for (const Vector3d& s : samples) {
    EXPECT_NEAR(s.y(), 1.0, 1e-12);
    EXPECT_LE(s.x(), 2.0 + 1e-9);  // the unseen right half is never sampled
  }
}

TEST(GroundTruthSamples, NoisyPointsAreProjectedAndUnlabelledIgnored) {
  SurfaceTestWorld w;
  w.addRectangle(1, "wall", rectangle({0, 1, 0}, {4, 0, 0}, {0, 0, 2.5}));
  w.addPoint({1, 1.03, 1}, 1, -1);
  w.addPoint({2, 0.98, 1}, 1, -1);
  w.addPoint({3, 0.5, 1}, -1, -1);  // true ray hit nothing
  const auto samples = groundTruthSamples(w.gt, w.points, Rigid2D{}, AccuracyOptions{});
  ASSERT_EQ(samples.size(), 2u);
  EXPECT_TRUE(samples[0].isApprox(Vector3d(1, 1, 1)));
  EXPECT_TRUE(samples[1].isApprox(Vector3d(2, 1, 1)));
}

TEST(MeshAccuracy, GroundTruthItselfHasNoError) {
  const SurfaceTestWorld w = halfSeenWall();
  const auto samples = groundTruthSamples(w.gt, w.points, Rigid2D{}, AccuracyOptions{});
  const MapAccuracy a = meshAccuracy(wallTriangles(0), w.gt, samples, Rigid2D{}, AccuracyOptions{});
  EXPECT_NEAR(a.gt_to_map.mean_m, 0, 1e-9);
  EXPECT_NEAR(a.gt_to_map.p95_m, 0, 1e-9);
  EXPECT_NEAR(a.map_to_gt.mean_m, 0, 1e-9);
  EXPECT_GT(a.map_to_gt.samples, 1000u);
}

TEST(MeshAccuracy, OffsetPlaneHasErrorEqualToTheOffset) {
  const SurfaceTestWorld w = halfSeenWall();
  const auto samples = groundTruthSamples(w.gt, w.points, Rigid2D{}, AccuracyOptions{});
  for (const double dy : {0.01, 0.05, -0.2}) {
    const MapAccuracy a =
        meshAccuracy(wallTriangles(dy), w.gt, samples, Rigid2D{}, AccuracyOptions{});
    EXPECT_NEAR(a.gt_to_map.mean_m, std::abs(dy), 1e-9);
    EXPECT_NEAR(a.gt_to_map.p95_m, std::abs(dy), 1e-9);
    EXPECT_NEAR(a.map_to_gt.mean_m, std::abs(dy), 1e-9);
  }
}

TEST(MeshAccuracy, TheAlignmentMovesTheMapIntoTheGroundTruthFrame) {
  const SurfaceTestWorld w = halfSeenWall();
  Rigid2D shift;
  shift.t = Eigen::Vector2d(0, 0.3);  // map frame = ground truth frame - 0.3 m in y
  MapPoints moved = w.points;
  for (Vector3d& p : moved.xyz)
    p.y() -= 0.3;
  const auto samples = groundTruthSamples(w.gt, moved, shift, AccuracyOptions{});
  const MapAccuracy a = meshAccuracy(wallTriangles(-0.3), w.gt, samples, shift, AccuracyOptions{});
  EXPECT_NEAR(a.gt_to_map.mean_m, 0, 1e-9);
  EXPECT_NEAR(a.map_to_gt.mean_m, 0, 1e-9);
}

TEST(MeshSamples, AreaWeightsSumToTheArea) {
  const WeightedPoints s = meshSamples(wallTriangles(0), 0.1);
  double area = 0;
  for (const double w : s.weight)
    area += w;
  EXPECT_NEAR(area, 10.0, 1e-9);
  EXPECT_EQ(s.xyz.size(), 2u * 48u * 48u);  // longest edge 4.72 m -> n = 48
}

TEST(PointAccuracy, OffsetPointsAndTheCap) {
  const SurfaceTestWorld w = halfSeenWall();
  const auto samples = groundTruthSamples(w.gt, w.points, Rigid2D{}, AccuracyOptions{});
  std::vector<Vector3d> pts;
  for (double x = 0.025; x < 4; x += 0.05) {
    for (double z = 0.025; z < 2.5; z += 0.05)
      pts.emplace_back(x, 1.02, z);
  }
  const MapAccuracy a = pointAccuracy(pts, w.gt, samples, Rigid2D{}, AccuracyOptions{});
  EXPECT_NEAR(a.map_to_gt.mean_m, 0.02, 1e-9);
  EXPECT_GT(a.gt_to_map.mean_m, 0.02);
  EXPECT_LT(a.gt_to_map.p95_m, std::sqrt(3 * 0.025 * 0.025) + 0.02);
  const MapAccuracy none = pointAccuracy({}, w.gt, samples, Rigid2D{}, AccuracyOptions{});
  EXPECT_DOUBLE_EQ(none.gt_to_map.mean_m, AccuracyOptions{}.index.max_distance_m);
}

}  // namespace
}  // namespace pmap::eval
