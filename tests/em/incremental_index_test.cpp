#include "pmap/em/incremental_index.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "em_test_worlds.h"

namespace pmap::em {
namespace {

Rectangle randomRect(std::mt19937_64& rng, const Eigen::Vector3d& at) {
  std::uniform_real_distribution<double> size(0.0, 3.0);
  const Eigen::Isometry3d T = testing::randomMotion(rng, 8.0);
  Rectangle r;
  r.normal = T.linear().col(2);
  r.axis_u = T.linear().col(0);
  r.centre = at + T.translation();
  r.offset = r.normal.dot(r.centre);
  r.half_u = size(rng);
  r.half_v = size(rng);
  return r;
}

Rectangle strip(double length_m) {
  Rectangle r;
  r.centre = {length_m / 2, 0, 0};
  r.half_u = length_m / 2;
  r.half_v = 2.0;
  return r;
}

// Every slot within `inflate` of p is a candidate; candidates ascending, once.
void expectNoMisses(const std::vector<Rectangle>& rects, const std::vector<char>& alive,
                    const IncrementalIndex& index, double inflate, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<std::int32_t> cand;
  for (int q = 0; q < 2000; ++q) {
    const Rectangle& r = rects[rng() % rects.size()];
    const Eigen::Vector3d p = r.centre + r.axis_u * (r.half_u + 0.3 * u(rng)) +
                              r.axisV() * (r.half_v * u(rng)) + r.normal * (0.3 * u(rng));
    index.candidates(p, cand);
    EXPECT_TRUE(std::is_sorted(cand.begin(), cand.end()));
    EXPECT_EQ(std::adjacent_find(cand.begin(), cand.end()), cand.end());
    for (std::size_t j = 0; j < rects.size(); ++j) {
      const bool in = std::binary_search(cand.begin(), cand.end(), static_cast<std::int32_t>(j));
      if (!alive[j]) {
        EXPECT_FALSE(in) << "removed slot " << j;
      } else if (rects[j].squaredDistance(p) <= inflate * inflate) {
        EXPECT_TRUE(in) << "missed slot " << j;
      }
    }
  }
}

TEST(IncrementalIndex, UpdatesAndRemovalsNeverMissASurface) {
  std::mt19937_64 rng(41);
  std::vector<Rectangle> rects;
  std::vector<char> alive;
  IncrementalIndex index(0.3);
  for (int j = 0; j < 30; ++j) {
    rects.push_back(randomRect(rng, {0, 0, 0}));
    alive.push_back(1);
    index.update(j, rects.back());
  }
  for (int j = 0; j < 30; j += 3) {  // move some, remove others
    rects[static_cast<std::size_t>(j)] = randomRect(rng, {0, 0, 0});
    index.update(j, rects[static_cast<std::size_t>(j)]);
    index.remove(j + 1);
    alive[static_cast<std::size_t>(j + 1)] = 0;
  }
  expectNoMisses(rects, alive, index, 0.3, rng);
}

// A surface stretched over 1e7 to 1e12 m (a mis-placed scan's points): it is
// listed for every point instead of rasterised (before: 1e7 cells and more,
// or an int overflow of the cell coordinates), and the index's cells follow
// the rectangles it does rasterise.
TEST(IncrementalIndex, Item12_IncrementalIndexMemoryIsBounded) {
  std::mt19937_64 rng(42);
  std::vector<Rectangle> rects;
  std::vector<char> alive;
  IncrementalIndex index(0.3);
  for (int j = 0; j < 20; ++j) {
    rects.push_back(randomRect(rng, {0, 0, 0}));
    alive.push_back(1);
    index.update(j, rects.back());
  }
  const std::size_t small_cells = index.indexedCells();
  EXPECT_EQ(index.globalCount(), 0u);
  for (const double far_m : {1e7, 1e9, 1e12}) {
    rects.push_back(strip(far_m));
    alive.push_back(1);
    index.update(static_cast<std::int32_t>(rects.size() - 1), rects.back());
  }
  EXPECT_EQ(index.indexedCells(), small_cells);
  EXPECT_EQ(index.globalCount(), 3u);
  expectNoMisses(rects, alive, index, 0.3, rng);
  std::vector<std::int32_t> cand;
  index.candidates({1e12, 0, 0}, cand);
  EXPECT_EQ(cand, (std::vector<std::int32_t>{20, 21, 22}));
  // Shrunk back to a room, the surface is rasterised again.
  rects[22] = strip(5.0);
  index.update(22, rects[22]);
  EXPECT_EQ(index.globalCount(), 2u);
  EXPECT_GT(index.indexedCells(), small_cells);
  expectNoMisses(rects, alive, index, 0.3, rng);
  for (std::int32_t j = 0; j < static_cast<std::int32_t>(rects.size()); ++j) {
    index.remove(j);
  }
  EXPECT_EQ(index.indexedCells(), 0u);
  EXPECT_EQ(index.globalCount(), 0u);
}

TEST(IncrementalIndex, Item12_ATotalCellBudgetSendsFurtherSurfacesGlobal) {
  std::mt19937_64 rng(43);
  std::vector<Rectangle> rects;
  std::vector<char> alive;
  IncrementalIndex index(0.3, 1.0, 200000, 500);
  for (int j = 0; j < 40; ++j) {
    rects.push_back(randomRect(rng, {0, 0, 0}));
    alive.push_back(1);
    index.update(j, rects.back());
  }
  EXPECT_LE(index.indexedCells(), 500u);
  EXPECT_GT(index.globalCount(), 0u);
  expectNoMisses(rects, alive, index, 0.3, rng);
}

}  // namespace
}  // namespace pmap::em
