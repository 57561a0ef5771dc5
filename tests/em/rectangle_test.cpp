#include "pmap/em/rectangle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "em_test_worlds.h"

namespace pmap::em {
namespace {

// A 4 m x 2 m rectangle in the plane z = 1, axis_u along x.
Rectangle floorTile() {
  Rectangle r;
  r.normal = {0, 0, 1};
  r.offset = 1.0;
  r.centre = {0, 0, 1};
  r.axis_u = {1, 0, 0};
  r.half_u = 2.0;
  r.half_v = 1.0;
  return r;
}

TEST(Rectangle, SquaredDistanceInsideIsThePlaneDistance) {
  const Rectangle r = floorTile();
  EXPECT_DOUBLE_EQ(r.squaredDistance({0.5, -0.5, 1.3}), 0.09);
  EXPECT_DOUBLE_EQ(r.squaredDistance({-1.9, 0.9, 0.8}), 0.04);
  EXPECT_DOUBLE_EQ(r.squaredDistance({1.0, 0.0, 1.0}), 0.0);
  EXPECT_NEAR(r.planeDistance({1.0, 0.0, 0.7}), -0.3, 1e-15);
}

TEST(Rectangle, SquaredDistanceBeyondAnEdgeAddsTheInPlaneGap) {
  const Rectangle r = floorTile();
  // 0.5 beyond the +u edge, 0.2 above: 0.25 + 0.04.
  EXPECT_DOUBLE_EQ(r.squaredDistance({2.5, 0.3, 1.2}), 0.29);
  // 0.3 beyond the -v edge, on the plane.
  EXPECT_NEAR(r.squaredDistance({0.0, -1.3, 1.0}), 0.09, 1e-15);
  // On the edge itself: zero.
  EXPECT_DOUBLE_EQ(r.squaredDistance({2.0, 0.0, 1.0}), 0.0);
}

TEST(Rectangle, SquaredDistanceBeyondACornerIsTheCornerDistance) {
  const Rectangle r = floorTile();
  const Eigen::Vector3d corner(2.0, 1.0, 1.0);
  const Eigen::Vector3d p(2.3, 1.4, 0.0);
  EXPECT_NEAR(r.squaredDistance(p), (p - corner).squaredNorm(), 1e-14);
}

TEST(Rectangle, SquaredDistanceIsTheClosestPointOfTheRectangle) {
  // Against a brute-force search over a fine grid of rectangle points.
  Rectangle r = floorTile();
  r.normal = Eigen::Vector3d(1, 2, 3).normalized();
  r.axis_u = Eigen::Vector3d(1, 0, 0);
  r.centre = {0.3, -0.2, 0.5};
  r.reproject();
  r.offset = r.normal.dot(r.centre);
  r.half_u = 0.7;
  r.half_v = 0.4;
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int k = 0; k < 50; ++k) {
    const Eigen::Vector3d p(u(rng), u(rng), u(rng));
    double best = 1e9;
    for (int a = -100; a <= 100; ++a) {
      for (int b = -100; b <= 100; ++b) {
        const Eigen::Vector3d q =
            r.centre + r.axis_u * (r.half_u * a / 100.0) + r.axisV() * (r.half_v * b / 100.0);
        best = std::min(best, (p - q).squaredNorm());
      }
    }
    EXPECT_LE(r.squaredDistance(p), best + 1e-12);
    EXPECT_NEAR(std::sqrt(r.squaredDistance(p)), std::sqrt(best), 0.01);
  }
}

TEST(Rectangle, UnboundedUsesThePlaneDistanceEverywhere) {
  Rectangle r = floorTile();
  r.bounded = false;
  EXPECT_DOUBLE_EQ(r.squaredDistance({100.0, -50.0, 1.5}), 0.25);
  r.half_u = r.half_v = 0.0;  // extents are irrelevant
  EXPECT_DOUBLE_EQ(r.squaredDistance({100.0, -50.0, 0.5}), 0.25);
}

TEST(Rectangle, ZeroSizedRectangleIsAPoint) {
  Rectangle r = floorTile();
  r.half_u = r.half_v = 0.0;
  EXPECT_DOUBLE_EQ(r.squaredDistance({1.0, 0.0, 1.0}), 1.0);
  EXPECT_DOUBLE_EQ(r.area(), 0.0);
}

TEST(Rectangle, CornersAreCounterClockwiseSeenFromTheNormal) {
  Rectangle r = floorTile();
  const auto c = r.corners();
  EXPECT_TRUE(c[0].isApprox(Eigen::Vector3d(-2, -1, 1)));
  EXPECT_TRUE(c[1].isApprox(Eigen::Vector3d(2, -1, 1)));
  EXPECT_TRUE(c[2].isApprox(Eigen::Vector3d(2, 1, 1)));
  EXPECT_TRUE(c[3].isApprox(Eigen::Vector3d(-2, 1, 1)));
  // Any orientation: each turn is to the left about the normal.
  std::mt19937_64 rng(8);
  for (int k = 0; k < 20; ++k) {
    const Eigen::Isometry3d T = testing::randomMotion(rng, 10.0);
    Rectangle m = floorTile();
    m.normal = T.linear() * m.normal;
    m.axis_u = T.linear() * m.axis_u;
    m.centre = T * m.centre;
    m.offset = m.normal.dot(m.centre);
    const auto q = m.corners();
    for (int i = 0; i < 4; ++i) {
      const Eigen::Vector3d e1 = q[(i + 1) % 4] - q[i];
      const Eigen::Vector3d e2 = q[(i + 2) % 4] - q[(i + 1) % 4];
      EXPECT_GT(e1.cross(e2).dot(m.normal), 0.0);
      EXPECT_NEAR(m.planeDistance(q[i]), 0.0, 1e-12);
    }
    EXPECT_NEAR((q[1] - q[0]).norm() * (q[2] - q[1]).norm(), m.area(), 1e-12);
  }
}

TEST(Rectangle, AxisVCompletesARightHandedFrame) {
  const Rectangle r = floorTile();
  EXPECT_TRUE(r.axisV().isApprox(Eigen::Vector3d::UnitY()));
  EXPECT_NEAR(r.axis_u.cross(r.axisV()).dot(r.normal), 1.0, 1e-15);
}

TEST(Rectangle, ReprojectPutsCentreAndAxisIntoThePlane) {
  Rectangle r;
  r.normal = Eigen::Vector3d(0, 1, 1).normalized();
  r.offset = 2.0;
  r.centre = {1, 1, 1};
  r.axis_u = {1, 1, 0};
  r.reproject();
  EXPECT_NEAR(r.planeDistance(r.centre), 0.0, 1e-14);
  EXPECT_NEAR(r.axis_u.norm(), 1.0, 1e-15);
  EXPECT_NEAR(r.axis_u.dot(r.normal), 0.0, 1e-15);
  // axis_u along the normal: any in-plane unit direction.
  r.axis_u = r.normal;
  r.reproject();
  EXPECT_NEAR(r.axis_u.norm(), 1.0, 1e-15);
  EXPECT_NEAR(r.axis_u.dot(r.normal), 0.0, 1e-15);
}

TEST(Rectangle, PlaneFromPointsFitsAWellShapedTriangle) {
  Rectangle r;
  const Eigen::Vector3d a(1, 0, 3), b(2, 0, 3), c(1, 1, 3);
  ASSERT_TRUE(planeFromPoints(a, b, c, r));
  EXPECT_NEAR(r.normal.norm(), 1.0, 1e-15);
  EXPECT_TRUE(r.normal.isApprox(Eigen::Vector3d::UnitZ()));  // (b-a) x (c-a)
  EXPECT_NEAR(r.offset, 3.0, 1e-14);
  for (const auto& p : {a, b, c}) {
    EXPECT_NEAR(r.planeDistance(p), 0.0, 1e-14);
  }
  EXPECT_NEAR(r.axis_u.dot(r.normal), 0.0, 1e-15);
  EXPECT_EQ(r.area(), 0.0);
  // Swapping two points flips the normal.
  ASSERT_TRUE(planeFromPoints(a, c, b, r));
  EXPECT_TRUE(r.normal.isApprox(-Eigen::Vector3d::UnitZ()));
  EXPECT_NEAR(r.offset, -3.0, 1e-14);
}

TEST(Rectangle, PlaneFromPointsRejectsDegenerateTriples) {
  Rectangle r;
  const Eigen::Vector3d a(1, 2, 3);
  EXPECT_FALSE(planeFromPoints(a, a, a, r));                             // coincident
  EXPECT_FALSE(planeFromPoints(a, a, a + Eigen::Vector3d(1, 0, 0), r));  // two coincident
  EXPECT_FALSE(planeFromPoints(a, a + Eigen::Vector3d(1, 1, 0), a + Eigen::Vector3d(3, 3, 0), r));
  // A sliver (height 1 mm over 1 m) is nearly collinear.
  EXPECT_FALSE(
      planeFromPoints(a, a + Eigen::Vector3d(1, 0, 0), a + Eigen::Vector3d(0.5, 0.001, 0), r));
  // The test is scale-free: the same well-shaped triangle at 1 mm and 1 km.
  for (const double s : {1e-3, 1e3}) {
    EXPECT_TRUE(planeFromPoints(a, a + Eigen::Vector3d(s, 0, 0), a + Eigen::Vector3d(0, s, 0), r));
  }
}

TEST(Rectangle, OverlapOfARectangleWithItselfIsItsArea) {
  const Rectangle r = floorTile();
  const Overlap o = overlapOf(r, r);
  EXPECT_NEAR(o.area_m2, 8.0, 1e-12);
  EXPECT_NEAR(o.max_separation_m, 0.0, 1e-12);
}

TEST(Rectangle, OverlapIsTheClippedProjection) {
  const Rectangle a = floorTile();
  Rectangle b = floorTile();
  b.centre = {1.0, 0.5, 1.03};  // 3 cm above, shifted by half its width in u and v
  b.offset = 1.03;
  // Overlap: u in [-1, 2], v in [-0.5, 1]: 3 x 1.5.
  const Overlap o = overlapOf(a, b);
  EXPECT_NEAR(o.area_m2, 4.5, 1e-12);
  EXPECT_NEAR(o.max_separation_m, 0.03, 1e-12);
  // Side by side: no overlap.
  b.centre = {5.0, 0.0, 1.0};
  EXPECT_EQ(overlapOf(a, b).area_m2, 0.0);
  // A square turned by 45 deg on the tile's centre: clipped to the tile.
  Rectangle c = floorTile();
  c.axis_u = Eigen::Vector3d(1, 1, 0).normalized();
  c.half_u = c.half_v = 1.0;  // 2 x 2, corners at distance sqrt(2) along the axes
  // Its corners at (+-1.414, 0) and (0, +-1.414); the tile cuts off the
  // two tips beyond v = +-1: each a triangle of height 0.414, area 0.414^2.
  const double tip = std::sqrt(2.0) - 1.0;
  EXPECT_NEAR(overlapOf(a, c).area_m2, 4.0 - 2.0 * tip * tip, 1e-12);
}

TEST(Rectangle, OverlapSeparationGrowsWithTheTiltAcrossTheOverlap) {
  const Rectangle a = floorTile();
  Rectangle b = floorTile();
  // Turned by 1 deg about the v axis through the centre: at u = +-2 the
  // planes are 2 tan(1 deg) = 3.5 cm apart.
  const double t = M_PI / 180.0;
  b.normal = {-std::sin(t), 0, std::cos(t)};
  b.axis_u = {std::cos(t), 0, std::sin(t)};
  b.offset = b.normal.dot(b.centre);
  const Overlap o = overlapOf(a, b);
  EXPECT_NEAR(o.max_separation_m, 2.0 * std::sin(t), 1e-3);
  EXPECT_NEAR(o.area_m2, 8.0 * std::cos(t), 1e-3);
}

}  // namespace
}  // namespace pmap::em
