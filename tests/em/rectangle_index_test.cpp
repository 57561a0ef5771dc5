#include "pmap/em/rectangle_index.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "em_test_worlds.h"

namespace pmap::em {
namespace {

std::vector<Surface> randomSurfaces(std::mt19937_64& rng, int n, const Eigen::Vector3d& at) {
  std::uniform_real_distribution<double> size(0.0, 3.0);
  std::vector<Surface> out;
  for (int k = 0; k < n; ++k) {
    const Eigen::Isometry3d T = testing::randomMotion(rng, 8.0);
    Surface s;
    s.rect.normal = T.linear().col(2);
    s.rect.axis_u = T.linear().col(0);
    s.rect.centre = at + T.translation();
    s.rect.offset = s.rect.normal.dot(s.rect.centre);
    s.rect.half_u = k % 7 == 0 ? 0.0 : size(rng);  // some degenerate (just seeded)
    s.rect.half_v = size(rng);
    s.rect.bounded = k % 11 != 5;
    s.id = k;
    out.push_back(s);
  }
  return out;
}

void expectNoMisses(const std::vector<Surface>& surfaces, const RectangleIndex& index,
                    const Eigen::Vector3d& at, double inflate, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-11.0, 11.0);
  std::vector<std::int32_t> cand;
  int near_pairs = 0;
  for (int q = 0; q < 3000; ++q) {
    // Half of the queries close to a random surface, half anywhere.
    Eigen::Vector3d p = at + Eigen::Vector3d(u(rng), u(rng), u(rng));
    if (q % 2 == 0) {
      const Rectangle& r = surfaces[rng() % surfaces.size()].rect;
      p = r.centre + r.axis_u * (r.half_u + 0.1 * u(rng)) + r.axisV() * (r.half_v * u(rng) / 11) +
          r.normal * (0.1 * u(rng) / 11);
    }
    index.candidates(p, cand);
    EXPECT_TRUE(std::is_sorted(cand.begin(), cand.end()));
    EXPECT_EQ(std::adjacent_find(cand.begin(), cand.end()), cand.end());
    for (std::size_t j = 0; j < surfaces.size(); ++j) {
      if (surfaces[j].rect.squaredDistance(p) <= inflate * inflate) {
        ++near_pairs;
        EXPECT_TRUE(std::binary_search(cand.begin(), cand.end(), static_cast<std::int32_t>(j)))
            << "missed surface " << j << " at query " << q;
      }
    }
  }
  EXPECT_GT(near_pairs, 500);  // the test exercised the boundary
}

TEST(RectangleIndex, EmptyIndexHasNoCandidates) {
  std::vector<std::int32_t> cand = {7};
  RectangleIndex().candidates({0, 0, 0}, cand);
  EXPECT_TRUE(cand.empty());
  RectangleIndex({}, 0.5).candidates({1, 2, 3}, cand);
  EXPECT_TRUE(cand.empty());
}

TEST(RectangleIndex, NeverMissesASurfaceWithinTheInflation) {
  std::mt19937_64 rng(31);
  for (const double inflate : {0.13, 0.5}) {
    for (const double cell : {0.25, 1.0}) {
      const Eigen::Vector3d at(0, 0, 0);
      const auto surfaces = randomSurfaces(rng, 40, at);
      const RectangleIndex index(surfaces, inflate, cell);
      expectNoMisses(surfaces, index, at, inflate, rng);
    }
  }
}

TEST(RectangleIndex, NeverMissesFarFromTheOrigin) {
  std::mt19937_64 rng(32);
  const Eigen::Vector3d at(1e5, -1e5, 30.0);
  const auto surfaces = randomSurfaces(rng, 30, at);
  expectNoMisses(surfaces, RectangleIndex(surfaces, 0.2, 1.0), at, 0.2, rng);
}

TEST(RectangleIndex, LargeAndUnboundedSurfacesAreEverywhere) {
  std::mt19937_64 rng(33);
  const auto surfaces = randomSurfaces(rng, 20, {0, 0, 0});
  // max_cells = 1: every bounded rectangle spans more cells and goes global.
  const RectangleIndex index(surfaces, 0.1, 1.0, 1);
  std::vector<std::int32_t> cand;
  index.candidates({1e4, 1e4, 1e4}, cand);
  EXPECT_EQ(cand, testing::allIndices(surfaces.size()));
  // Only unbounded planes are global with the default limit.
  const RectangleIndex normal(surfaces, 0.1);
  normal.candidates({1e4, 1e4, 1e4}, cand);
  std::vector<std::int32_t> unbounded;
  for (std::size_t j = 0; j < surfaces.size(); ++j) {
    if (!surfaces[j].rect.bounded) {
      unbounded.push_back(static_cast<std::int32_t>(j));
    }
  }
  ASSERT_FALSE(unbounded.empty());
  EXPECT_EQ(cand, unbounded);
}

// Rectangles spanning up to 1e12 m (a surface stretched by a mis-placed
// scan) and many large ones: the index holds at most its cell budget, the
// rest are listed for every point, and nothing within the inflation is
// missed (before: a 1e12 m rectangle overflowed int cell coordinates).
TEST(RectangleIndex, Item12_RectangleIndexMemoryIsBounded) {
  std::mt19937_64 rng(34);
  auto surfaces = randomSurfaces(rng, 30, {0, 0, 0});
  for (const double far_m : {1e7, 1e9, 1e12}) {
    Surface s;
    s.rect.centre = {far_m / 2, 0, 0};
    s.rect.half_u = far_m / 2;
    s.rect.half_v = 2.0;
    surfaces.push_back(s);
  }
  const RectangleIndex index(surfaces, 0.2, 1.0);
  EXPECT_LE(index.indexedCells(), 2000000u);
  expectNoMisses(surfaces, index, {0, 0, 0}, 0.2, rng);
  std::vector<std::int32_t> cand;
  index.candidates({1e12, 0, 0}, cand);
  EXPECT_TRUE(std::binary_search(cand.begin(), cand.end(), 32));
  // A total budget of 2000 cells: the smallest rectangles are indexed, the
  // others are global, and candidates stay exact supersets.
  const RectangleIndex small(surfaces, 0.2, 1.0, 200000, 2000);
  EXPECT_LE(small.indexedCells(), 2000u);
  EXPECT_GT(small.indexedCells(), 0u);
  EXPECT_GE(small.globalCount(), 3u);
  expectNoMisses(surfaces, small, {0, 0, 0}, 0.2, rng);
}

}  // namespace
}  // namespace pmap::em
