// Issue 16: sigma_m = auto. The estimate recovers the noise of planes it is
// given, ignores a minority of clutter, and is deterministic.
#include "pmap/em/noise_estimate.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace pmap::em {
namespace {

// Points on the three planes of a room corner (x = 0, y = 0, z = 0), 4 x 3 m
// each, a point every `spacing` m, with Gaussian noise `sigma` along each
// plane's normal.
std::vector<Eigen::Vector3d> corner(double sigma, double spacing, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, sigma);
  std::vector<Eigen::Vector3d> out;
  for (double u = 0.05; u < 4.0; u += spacing) {
    for (double v = 0.05; v < 3.0; v += spacing) {
      out.emplace_back(n(rng), u, v);
      out.emplace_back(u, n(rng), v);
      out.emplace_back(u, v, n(rng));
    }
  }
  return out;
}

// Accurate while the noise is small against the k = 100 neighbourhood's
// radius r (100 points of a plane sampled every s metres lie within about
// r = 5.6 s): sigma / r = 0.09 and 0.18 here.
TEST(NoiseEstimate, Item16_RecoversThePlanesNoise) {
  for (const auto& [sigma, spacing] :
       {std::pair<double, double>{0.005, 0.01}, {0.02, 0.02}, {0.05, 0.05}}) {
    const NoiseEstimate e = estimateRangeSigma(corner(sigma, spacing, 3));
    ASSERT_TRUE(e.estimated);
    EXPECT_EQ(e.samples, 2000);
    EXPECT_NEAR(e.sigma_m, sigma, 0.15 * sigma) << "sigma " << sigma;
    EXPECT_LE(e.p25_m, e.sigma_m);
    EXPECT_GE(e.p75_m, e.sigma_m);
  }
}

// Where the noise is as large as a fair part of the neighbourhood, the k
// nearest points in 3D are picked close to the query across the plane too,
// and the estimate is low (measured: 3.9 cm for 5 cm of noise on a plane
// sampled every 2 cm, sigma / r = 0.45): a bias of the rule, said in em.md.
TEST(NoiseEstimate, Item16_NoiseLargeAgainstTheNeighbourhoodIsUnderestimated) {
  const NoiseEstimate e = estimateRangeSigma(corner(0.05, 0.02, 3));
  EXPECT_LT(e.sigma_m, 0.05);
  EXPECT_GT(e.sigma_m, 0.02);
}

TEST(NoiseEstimate, Item16_AMinorityOfClutterDoesNotMoveTheMedian) {
  std::vector<Eigen::Vector3d> points = corner(0.02, 0.02, 5);
  const std::size_t planes = points.size();
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(1.0, 2.0);
  for (std::size_t i = 0; i < planes / 5; ++i) {  // a box of scattered clutter, 1/6 of all
    points.emplace_back(u(rng), u(rng), u(rng));
  }
  const NoiseEstimate e = estimateRangeSigma(points);
  EXPECT_NEAR(e.sigma_m, 0.02, 0.004);
  EXPECT_GT(e.p75_m, e.sigma_m);
}

TEST(NoiseEstimate, Item16_FloorTooFewPointsAndDeterminism) {
  const std::vector<Eigen::Vector3d> flat = corner(0.0, 0.05, 1);
  EXPECT_DOUBLE_EQ(estimateRangeSigma(flat).sigma_m, 0.002);  // exact planes: the floor
  const std::vector<Eigen::Vector3d> few(100, Eigen::Vector3d::Zero());
  EXPECT_FALSE(estimateRangeSigma(few).estimated);  // k + 1 = 101 needed
  const std::vector<Eigen::Vector3d> noisy = corner(0.03, 0.03, 2);
  EXPECT_EQ(estimateRangeSigma(noisy).sigma_m, estimateRangeSigma(noisy).sigma_m);
  NoiseEstimateOptions o;
  std::string why;
  EXPECT_TRUE(o.validate(&why));
  o.neighbours = 2;
  EXPECT_FALSE(o.validate(&why));
}

}  // namespace
}  // namespace pmap::em
