#include "pmap/eval/rectangle_errors.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pmap::eval {
namespace {

const Rectangle kRect = {Eigen::Vector3d(0, 0, 0), {4, 0, 0}, {4, 0, 2}, {0, 0, 2}};

TEST(RectangleErrors, NormalAngleIsSignAgnostic) {
  EXPECT_NEAR(normalAngleDeg({0, 1, 0}, {0, -1, 0}), 0.0, 1e-12);
  EXPECT_NEAR(normalAngleDeg({0, 1, 0}, {0, 2, 0}), 0.0, 1e-12);
  EXPECT_NEAR(normalAngleDeg({1, 0, 0}, {0, 1, 0}), 90.0, 1e-12);
  const double a = 15.0 * M_PI / 180.0;
  EXPECT_NEAR(normalAngleDeg({1, 0, 0}, {-std::cos(a), std::sin(a), 0}), 15.0, 1e-9);
  EXPECT_NEAR(normalAngleDeg({1, 0, 0}, {1, 1e-9, 0}), 180.0 / M_PI * 1e-9, 1e-15);
  EXPECT_EQ(normalAngleDeg({0, 0, 0}, {1, 0, 0}), 90.0);
}

TEST(RectangleErrors, PlaneDistanceAndCentre) {
  EXPECT_NEAR(planeDistance({0, 0, 1}, 2.0, {5, 5, 2.5}), 0.5, 1e-12);
  EXPECT_NEAR(planeDistance({0, 0, -1}, -2.0, {5, 5, 1.5}), 0.5, 1e-12);
  EXPECT_EQ(rectangleCentre(kRect), Eigen::Vector3d(2, 0, 1));
}

TEST(RectangleErrors, CornerCorrespondenceIgnoresStartAndOrder) {
  EXPECT_NEAR(cornerError(kRect, kRect), 0.0, 1e-12);
  const Rectangle shifted = {kRect[2], kRect[3], kRect[0], kRect[1]};
  EXPECT_NEAR(cornerError(shifted, kRect), 0.0, 1e-12);
  const Rectangle reversed = {kRect[3], kRect[2], kRect[1], kRect[0]};
  EXPECT_NEAR(cornerError(reversed, kRect), 0.0, 1e-12);
  EXPECT_NEAR(cornerError(kRect, reversed), 0.0, 1e-12);
  const Rectangle reversed_shifted = {kRect[1], kRect[0], kRect[3], kRect[2]};
  EXPECT_NEAR(cornerError(reversed_shifted, kRect), 0.0, 1e-12);
}

TEST(RectangleErrors, CornerErrorIsTheMeanCornerDistance) {
  // Map rectangle 0.1 m in front and 0.3 m wider on the right: corners 0, 3
  // are 0.1 m off, corners 1, 2 sqrt(0.1^2 + 0.3^2) m; listed reversed.
  const Eigen::Vector3d front(0, 0.1, 0);
  const Eigen::Vector3d right(0.3, 0, 0);
  const Rectangle map = {kRect[3] + front, kRect[2] + front + right, kRect[1] + front + right,
                         kRect[0] + front};
  EXPECT_NEAR(cornerError(map, kRect), (0.1 + std::sqrt(0.1)) / 2.0, 1e-12);
}

}  // namespace
}  // namespace pmap::eval
