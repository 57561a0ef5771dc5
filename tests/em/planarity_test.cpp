#include "pmap/em/planarity.h"

#include <gtest/gtest.h>

#include <numeric>

#include "em_test_worlds.h"
#include "pmap/em/surface_fit.h"

namespace pmap::em {
namespace {

// A depth a bend must reach to count
// (as config/mrpt-rgbd.ini's min_curvature_depth_m).
constexpr double kTwoSigma = 0.04;

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
  EXPECT_FALSE(isCurved(measurePlanarity(c.points, all(c.points.size()), r), 1.0, kTwoSigma));
}

TEST(Planarity, ABinIsCurved) {
  std::mt19937_64 rng(3);
  testing::Cloud c;
  testing::addCylinder(c, {0, 0, 0.3}, 0.24, 0.8, 0.03, 0.02, rng, 0);
  Rectangle r;
  ASSERT_EQ(fitSurface(c.points, all(c.points.size()), r), FitStatus::kOk);
  const Planarity p = measurePlanarity(c.points, all(c.points.size()), r);
  EXPECT_LT(p.curvature_radius_m, 0.5);
  EXPECT_TRUE(isCurved(p, 1.0, kTwoSigma));
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
  EXPECT_TRUE(isCurved(measurePlanarity(c.points, strip, r), 1.0, kTwoSigma));
}

TEST(Planarity, AWallFarFromTheOriginIsStillFlat) {
  std::mt19937_64 rng(9);
  testing::Cloud c;
  testing::addPlane(c, {1e6, -2e5, 10}, {0, 1, 0}, {0, 0, 1}, 30.0, 2.5, 0.1, 0.02, rng);
  Rectangle r;
  ASSERT_EQ(fitSurface(c.points, all(c.points.size()), r), FitStatus::kOk);
  EXPECT_FALSE(isCurved(measurePlanarity(c.points, all(c.points.size()), r), 1.0, kTwoSigma));
}

// A strip 0.4 m wide cut from a cylinder of radius 0.8 m bends 2.5 cm deep
// across: below the radius limit, yet within 2 sigma of a plane (what a
// range camera's depth distortion does to a flat wall). Its depth is
// measured as the sagitta k L^2 / 8.
TEST(Planarity, AShallowBendIsWithinTheNoiseOfAPlane) {
  std::mt19937_64 rng(11);
  testing::Cloud c;
  testing::addCylinder(c, {0, 0, 0}, 0.8, 0.6, 0.01, 0.003, rng, 0);
  std::vector<std::int32_t> strip;
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    if (c.points[i].x() < -0.775) {
      strip.push_back(static_cast<std::int32_t>(i));
    }
  }
  Rectangle r;
  ASSERT_EQ(fitSurface(c.points, strip, r), FitStatus::kOk);
  const Planarity p = measurePlanarity(c.points, strip, r);
  EXPECT_NEAR(p.curvature_radius_m, 0.8, 0.1);
  EXPECT_NEAR(p.bend_depth_m, 0.025, 0.008);  // the fitted quadratic's sagitta: 3.1 cm
  EXPECT_FALSE(isCurved(p, 1.0, kTwoSigma));
  EXPECT_TRUE(isCurved(p, 1.0, 0.01));  // as deep as 1 cm: curved
}

}  // namespace
}  // namespace pmap::em
