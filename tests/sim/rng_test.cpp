#include "pmap/sim/rng.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pmap::sim {
namespace {

TEST(Rng, SameSeedSameSequence) {
  Rng a(42);
  Rng b(42);
  for (int i = 0; i < 100; ++i) {
    EXPECT_EQ(a.uniform(), b.uniform());
    EXPECT_EQ(a.normal(), b.normal());
  }
}

TEST(Rng, NormalHasUnitVarianceAndZeroMean) {
  Rng rng(7);
  double sum = 0.0;
  double sum2 = 0.0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double x = rng.normal();
    ASSERT_TRUE(std::isfinite(x));
    sum += x;
    sum2 += x * x;
  }
  EXPECT_NEAR(sum / n, 0.0, 0.01);
  EXPECT_NEAR(sum2 / n, 1.0, 0.01);
}

TEST(Rng, UniformStaysInRange) {
  Rng rng(1);
  for (int i = 0; i < 10000; ++i) {
    const double u = rng.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    const int k = rng.uniformInt(-3, 3);
    ASSERT_GE(k, -3);
    ASSERT_LE(k, 3);
  }
}

TEST(Rng, DerivedSeedsDifferByStreamAndIndex) {
  EXPECT_NE(deriveSeed(1, "laser", 0), deriveSeed(1, "laser", 1));
  EXPECT_NE(deriveSeed(1, "laser", 0), deriveSeed(1, "image", 0));
  EXPECT_NE(deriveSeed(1, "laser", 0), deriveSeed(2, "laser", 0));
  EXPECT_EQ(deriveSeed(5, "poster", 3), deriveSeed(5, "poster", 3));
}

}  // namespace
}  // namespace pmap::sim
