#include "pmap/em/planarity.h"

#include <gtest/gtest.h>

#include <numeric>

#include "em_test_worlds.h"
#include "pmap/em/surface_fit.h"

namespace pmap::em {
namespace {

std::vector<std::int32_t> all(std::size_t n) {
  std::vector<std::int32_t> v(n);
  std::iota(v.begin(), v.end(), 0);
  return v;
}

TEST(Planarity, ANoisyPlaneIsFlat) {
  std::mt19937_64 rng(3);
  testing::Cloud c;
  testing::addPlane(c, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 3.0, 2.0, 0.05, 0.02, rng);
  Rectangle r;
  ASSERT_EQ(fitSurface(c.points, all(c.points.size()), r), FitStatus::kOk);
  EXPECT_FALSE(isCurved(measurePlanarity(c.points, all(c.points.size()), r), 1.0));
}

TEST(Planarity, ABinIsCurved) {
  std::mt19937_64 rng(3);
  testing::Cloud c;
  testing::addCylinder(c, {0, 0, 0.3}, 0.24, 0.8, 0.03, 0.02, rng, 0);
  Rectangle r;
  ASSERT_EQ(fitSurface(c.points, all(c.points.size()), r), FitStatus::kOk);
  const Planarity p = measurePlanarity(c.points, all(c.points.size()), r);
  EXPECT_LT(p.curvature_radius_m, 0.5);
  EXPECT_TRUE(isCurved(p, 1.0));
}

TEST(Planarity, AFrontStripOfABinIsCurved) {
  std::mt19937_64 rng(5);
  testing::Cloud c;
  testing::addCylinder(c, {0, 0, 0.3}, 0.24, 0.4, 0.02, 0.02, rng, 0);
  // Keep the strip within 12 cm of the front (x <= -0.12): what a tangent
  // plane would explain.
  std::vector<std::int32_t> strip;
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    if (c.points[i].x() < -0.12) {
      strip.push_back(static_cast<std::int32_t>(i));
    }
  }
  Rectangle r;
  ASSERT_EQ(fitSurface(c.points, strip, r), FitStatus::kOk);
  EXPECT_TRUE(isCurved(measurePlanarity(c.points, strip, r), 1.0));
}

TEST(Planarity, AWallFarFromTheOriginIsStillFlat) {
  std::mt19937_64 rng(9);
  testing::Cloud c;
  testing::addPlane(c, {1e6, -2e5, 10}, {0, 1, 0}, {0, 0, 1}, 30.0, 2.5, 0.1, 0.02, rng);
  Rectangle r;
  ASSERT_EQ(fitSurface(c.points, all(c.points.size()), r), FitStatus::kOk);
  EXPECT_FALSE(isCurved(measurePlanarity(c.points, all(c.points.size()), r), 1.0));
}

}  // namespace
}  // namespace pmap::em
