// The sample of coarse-to-fine (subsample.h): exact size, input order, the
// same sample for the same seed, neighbours among the sampled points, and
// the thresholds scaled by the sampled fraction.
#include "pmap/em/subsample.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "em_test_worlds.h"

namespace pmap::em {
namespace {

testing::Cloud plane() {
  testing::Cloud c;
  std::mt19937_64 rng(4);
  testing::addPlane(c, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 4.0, 3.0, 0.02, 0.005, rng);
  return c;
}

TEST(Subsample, DrawsExactlyTheTargetInInputOrderAndIsSeeded) {
  const testing::Cloud c = plane();
  ASSERT_GT(c.points.size(), 20000u);
  const Subsample s = drawSubsample(c.points, c.neighbours(), c.rows, 3000, 7);
  ASSERT_EQ(s.index.size(), 3000u);
  EXPECT_TRUE(std::is_sorted(s.index.begin(), s.index.end()));
  EXPECT_EQ(std::adjacent_find(s.index.begin(), s.index.end()), s.index.end());
  EXPECT_NEAR(s.fraction, 3000.0 / static_cast<double>(c.points.size()), 1e-12);
  ASSERT_EQ(s.points.size(), 3000u);
  ASSERT_EQ(s.rows.size(), 3000u);
  for (std::size_t k = 0; k < s.index.size(); ++k) {
    EXPECT_EQ(s.points[k], c.points[static_cast<std::size_t>(s.index[k])]);
    EXPECT_EQ(s.rows[k], c.rows[static_cast<std::size_t>(s.index[k])]);
  }
  EXPECT_EQ(drawSubsample(c.points, c.neighbours(), c.rows, 3000, 7).index, s.index);
  EXPECT_NE(drawSubsample(c.points, c.neighbours(), c.rows, 3000, 8).index, s.index);
  // More than there are: all of them.
  EXPECT_EQ(drawSubsample(c.points, c.neighbours(), {}, c.points.size() + 5, 7).index.size(),
            c.points.size());
}

TEST(Subsample, NeighboursAreNearbySampledPoints) {
  const testing::Cloud c = plane();  // 2 cm spacing
  const Subsample s = drawSubsample(c.points, c.neighbours(), c.rows, 3000, 7);
  // A uniform sample of ~1/10 of a 2 cm grid is ~6 cm apart: most points
  // have all four neighbours, each within 2.5 x that.
  std::size_t with_four = 0;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    int n = 0;
    for (const std::int32_t j : s.neighbours[i]) {
      if (j >= 0) {
        ASSERT_LT(static_cast<std::size_t>(j), s.points.size());
        EXPECT_NE(static_cast<std::size_t>(j), i);
        EXPECT_LT((s.points[static_cast<std::size_t>(j)] - s.points[i]).norm(), 0.2);
        ++n;
      }
    }
    with_four += n == 4 ? 1 : 0;
  }
  EXPECT_GT(with_four, s.points.size() * 9 / 10);
}

TEST(Subsample, ThresholdsThatCountPointsOrNatsAreScaled) {
  PlanarEmOptions o;
  o.coarse_points = 5000;
  const PlanarEmOptions s = scaledToSample(o, 0.1);
  EXPECT_DOUBLE_EQ(s.kappa, 0.1 * o.kappa);
  EXPECT_DOUBLE_EQ(s.min_gain, 0.1 * o.min_gain);
  EXPECT_DOUBLE_EQ(s.empty_area_cost, 0.1 * o.empty_area_cost);
  EXPECT_DOUBLE_EQ(s.convergence_absolute_nats, 0.1 * o.convergence_absolute_nats);
  EXPECT_EQ(s.min_support, 8);  // 60 x 0.1 = 6, floored at rules.min_part_points
  EXPECT_EQ(s.coarse_points, 0);
  EXPECT_DOUBLE_EQ(s.sigma_m, o.sigma_m);  // the measurement model is the same
  std::string why;
  EXPECT_TRUE(s.validate(&why)) << why;
}

}  // namespace
}  // namespace pmap::em
