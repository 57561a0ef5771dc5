// Nearest-triangle distances: closest points by region, the grid search
// against brute force, caps, degenerate triangles and bad input.
#include "pmap/eval/triangle_index.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace pmap::eval {
namespace {
using Eigen::Vector3d;

const Triangle3 kUnit{Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0)};

TEST(ClosestPointOnTriangle, InteriorEdgeAndVertexRegions) {
  EXPECT_TRUE(closestPointOnTriangle(kUnit, {0.2, 0.2, 0.5}).isApprox(Vector3d(0.2, 0.2, 0)));
  EXPECT_TRUE(closestPointOnTriangle(kUnit, {0.5, -1, 0}).isApprox(Vector3d(0.5, 0, 0)));
  EXPECT_TRUE(closestPointOnTriangle(kUnit, {1, 1, 0}).isApprox(Vector3d(0.5, 0.5, 0)));
  EXPECT_TRUE(closestPointOnTriangle(kUnit, {-1, -1, 3}).isApprox(Vector3d(0, 0, 0)));
  EXPECT_TRUE(closestPointOnTriangle(kUnit, {2, -0.5, 0}).isApprox(Vector3d(1, 0, 0)));
}

TEST(ClosestPointOnTriangle, DegenerateTrianglesArePointsAndSegments) {
  const Triangle3 point{Vector3d(1, 2, 3), Vector3d(1, 2, 3), Vector3d(1, 2, 3)};
  EXPECT_TRUE(closestPointOnTriangle(point, {0, 0, 0}).isApprox(Vector3d(1, 2, 3)));
  const Triangle3 segment{Vector3d(0, 0, 0), Vector3d(2, 0, 0), Vector3d(1, 0, 0)};
  EXPECT_TRUE(closestPointOnTriangle(segment, {1.5, 1, 0}).isApprox(Vector3d(1.5, 0, 0)));
}

// The nearest triangle's distance by looking at every one, at most cap.
double bruteForceDistance(const std::vector<Triangle3>& tris, const Vector3d& p, double cap) {
  double best = cap;
  for (const auto& t : tris)
    best = std::min(best, (closestPointOnTriangle(t, p) - p).norm());
  return best;
}

TEST(TriangleIndex, MatchesBruteForce) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-3, 3);
  std::vector<Triangle3> tris;
  for (int k = 0; k < 200; ++k) {
    const Vector3d a(u(rng), u(rng), u(rng));
    tris.push_back({a, a + 0.3 * Vector3d(u(rng), u(rng), u(rng)),
                    a + 0.3 * Vector3d(u(rng), u(rng), u(rng))});
  }
  TriangleIndexOptions o;
  o.max_distance_m = 10;
  const TriangleIndex index(tris, o);
  for (int q = 0; q < 300; ++q) {
    const Vector3d p(u(rng), u(rng), u(rng));
    EXPECT_EQ(index.distance(p), bruteForceDistance(tris, p, 10));  // the exact minimum
  }
}

// Queries around and far outside the triangles' box: the same distances as
// brute force.
TEST(TriangleIndex, QueriesOutsideTheTrianglesBoxMatchBruteForce) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1), far(-6, 6);
  std::vector<Triangle3> tris;
  for (int k = 0; k < 100; ++k) {
    const Vector3d a(2 * u(rng), 2 * u(rng), 0.5 * u(rng));  // a flat slab of triangles
    tris.push_back({a, a + 0.3 * Vector3d(u(rng), u(rng), u(rng)),
                    a + 0.3 * Vector3d(u(rng), u(rng), u(rng))});
  }
  TriangleIndexOptions o;
  o.max_distance_m = 3;
  const TriangleIndex index(tris, o);
  for (int q = 0; q < 2000; ++q) {
    const Vector3d p(far(rng), far(rng), far(rng));
    EXPECT_EQ(index.distance(p), bruteForceDistance(tris, p, o.max_distance_m)) << p.transpose();
  }
}

// Building-sized triangles (walls 20 m long beside 5 cm ones, as a ground
// truth's rectangles and a map's fine triangles), many of them: still the
// exact minimum.
TEST(TriangleIndex, LargeAndSmallTrianglesMatchBruteForce) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Triangle3> tris;
  for (int k = 0; k < 3000; ++k) {
    const Vector3d a(10 * u(rng), 10 * u(rng), 1.5 + 1.5 * u(rng));
    const double size = k % 50 == 0 ? 20.0 : 0.05;
    tris.push_back({a, a + size * Vector3d(u(rng), u(rng), 0.1 * u(rng)),
                    a + size * Vector3d(u(rng), 0.1 * u(rng), u(rng))});
  }
  TriangleIndexOptions o;
  o.max_distance_m = 3;
  const TriangleIndex index(tris, o);
  for (int q = 0; q < 1000; ++q) {
    const Vector3d p(14 * u(rng), 14 * u(rng), 1.5 + 4 * u(rng));
    EXPECT_EQ(index.distance(p), bruteForceDistance(tris, p, o.max_distance_m)) << p.transpose();
  }
}

TEST(TriangleIndex, FarAndEmptyAreCapped) {
  TriangleIndexOptions o;
  o.max_distance_m = 1.0;
  EXPECT_DOUBLE_EQ(TriangleIndex({}, o).distance({0, 0, 0}), 1.0);
  EXPECT_DOUBLE_EQ(TriangleIndex({kUnit}, o).distance({0, 0, 5}), 1.0);
  EXPECT_NEAR(TriangleIndex({kUnit}, o).distance({0.1, 0.1, 0.4}), 0.4, 1e-12);
}

TEST(TriangleIndex, RejectsBadOptionsAndCorners) {
  TriangleIndexOptions o;
  o.max_distance_m = 0;
  std::string why;
  EXPECT_FALSE(o.validate(&why));
  EXPECT_NE(why.find("max_distance_m"), std::string::npos);
  EXPECT_THROW(TriangleIndex({kUnit}, o), std::invalid_argument);
  Triangle3 bad = kUnit;
  bad.b.x() = NAN;
  EXPECT_THROW(TriangleIndex({bad}, TriangleIndexOptions{}), std::invalid_argument);
}

}  // namespace
}  // namespace pmap::eval
