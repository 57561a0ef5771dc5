#include "pmap/eval/ground_truth.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pmap::eval {
namespace {

TEST(GroundTruthGeometry, DistanceToRectangleInsideEdgeAndCorner) {
  // 2 x 1 rectangle in the plane z = 0.
  const std::array<Eigen::Vector3d, 4> r = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 0, 0),
                                            Eigen::Vector3d(2, 1, 0), Eigen::Vector3d(0, 1, 0)};
  EXPECT_NEAR(distanceToRectangle(r, {1, 0.5, 0.3}), 0.3, 1e-12);         // above the inside
  EXPECT_NEAR(distanceToRectangle(r, {1, -0.4, 0.3}), 0.5, 1e-12);        // beyond an edge
  EXPECT_NEAR(distanceToRectangle(r, {3, 2, 0}), std::sqrt(2.0), 1e-12);  // past a corner
  EXPECT_NEAR(distanceToRectangle(r, {0.5, 0.5, -0.2}), 0.2, 1e-12);
}

TEST(GroundTruthGeometry, CylinderAndBoxDistances) {
  GroundTruth gt;
  gt.cylinders.push_back({5, "bin", {0, 0}, 0.25, 0.0, 1.0});
  EXPECT_NEAR(gt.distance(5, {1.0, 0, 0.5}), 0.75, 1e-12);  // beside
  EXPECT_NEAR(gt.distance(5, {0.1, 0, 1.5}), 0.5, 1e-12);   // above the lid
  EXPECT_NEAR(gt.distance(5, {0.2, 0, 0.5}), 0.05, 1e-12);  // inside, near the side
  EXPECT_NEAR(gt.distance(5, {1.25, 0, 2.0}), std::sqrt(2.0), 1e-12);
  GtBox b;
  b.id = 6;
  b.min = {-0.5, -0.5, 0};
  b.max = {0.5, 0.5, 2};
  b.centre = {10, 0};
  b.yaw = M_PI / 4;
  gt.boxes.push_back(b);
  EXPECT_NEAR(gt.distance(6, {10 + 1.0, 0, 1}), 1.0 - std::sqrt(0.5), 1e-9);
  EXPECT_TRUE(std::isnan(gt.distance(99, {0, 0, 0})));
  EXPECT_TRUE(gt.isClutter(5));
  EXPECT_FALSE(gt.isClutter(99));
}

}  // namespace
}  // namespace pmap::eval
