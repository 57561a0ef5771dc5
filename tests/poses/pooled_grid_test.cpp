// Issue 15: the sparse, tiled max-pooled grid of the loop search holds the
// same values as a dense one, level by level, on and around the grid.
#include "pmap/poses/pooled_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace pmap::poses {
namespace {

// Dense reference: level h at (c, r) is the max of level 0 over
// [c, c + 2^h) x [r, r + 2^h) clipped to the grid; a window starting left
// of (below) the grid reads as if it started at 0, and 0 outside.
float denseAt(const std::vector<float>& g, int cols, int rows, int h, int c, int r) {
  const int w = 1 << h;
  if (c <= -w || r <= -w || c >= cols || r >= rows) {
    return 0.0f;
  }
  c = std::max(c, 0);
  r = std::max(r, 0);
  float m = 0.0f;
  for (int y = r; y < std::min(rows, r + w); ++y) {
    for (int x = c; x < std::min(cols, c + w); ++x) {
      m = std::max(m, g[static_cast<std::size_t>(y) * cols + x]);
    }
  }
  return m;
}

TEST(PooledGrid, Item15_EqualsADenseMaxPoolEverywhere) {
  for (const auto& [cols, rows] : {std::pair<int, int>{61, 45}, {8, 8}, {1, 17}, {130, 9}}) {
    std::mt19937 rng(static_cast<unsigned>(cols * 100 + rows));
    std::uniform_int_distribution<int> uc(0, cols - 1), ur(0, rows - 1);
    std::uniform_real_distribution<float> v(0.0f, 1.0f);
    std::vector<float> dense(static_cast<std::size_t>(cols) * rows, 0.0f);
    PooledGrid grid(cols, rows);
    for (int i = 0; i < 40; ++i) {  // sparse points, some raised twice
      const int c = uc(rng), r = ur(rng);
      const float x = v(rng);
      grid.raise(c, r, x);
      float& d = dense[static_cast<std::size_t>(r) * cols + c];
      d = std::max(d, x);
    }
    grid.pool(7);
    ASSERT_EQ(grid.levels(), 7);
    for (int h = 0; h < 7; ++h) {
      for (int r = -70; r < rows + 3; ++r) {
        for (int c = -70; c < cols + 3; ++c) {
          ASSERT_EQ(grid.at(h, c, r), denseAt(dense, cols, rows, h, c, r))
              << cols << " x " << rows << ", level " << h << " at " << c << ", " << r;
        }
      }
    }
  }
}

// A run of cells raised at once (raiseRow, across tile edges) holds what
// raising each cell alone holds.
TEST(PooledGrid, Item15_ARowRaisedAtOnceEqualsItsCellsOneByOne) {
  const int cols = 45, rows = 20;
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> uc(0, cols - 1), ur(0, rows - 1), un(1, 19);
  std::uniform_real_distribution<float> v(0.0f, 1.0f);
  PooledGrid runs(cols, rows), cells(cols, rows);
  for (int i = 0; i < 60; ++i) {
    const int r = ur(rng), c = uc(rng), n = std::min(un(rng), cols - c);
    std::vector<float> values(static_cast<std::size_t>(n));
    for (float& x : values) {
      x = v(rng);
    }
    runs.raiseRow(c, r, values.data(), n);
    for (int k = 0; k < n; ++k) {
      cells.raise(c + k, r, values[static_cast<std::size_t>(k)]);
    }
  }
  runs.pool(3);
  cells.pool(3);
  for (int h = 0; h < 3; ++h) {
    for (int r = 0; r < rows; ++r) {
      for (int c = 0; c < cols; ++c) {
        ASSERT_EQ(runs.at(h, c, r), cells.at(h, c, r)) << "level " << h << " at " << c << ", " << r;
      }
    }
  }
  EXPECT_EQ(runs.tiles(), cells.tiles());
}

// Tiles are allocated only near non-zero cells: one point in a large grid
// takes a few tiles per level, not the grid.
TEST(PooledGrid, Item15_StoresOnlyTilesNearTheData) {
  PooledGrid grid(2000, 2000);
  grid.raise(1000, 1000, 1.0f);
  grid.pool(7);
  EXPECT_LE(grid.tiles(), 7u * 81u);  // at most 9 x 9 tiles per level (64-cell windows)
  EXPECT_EQ(grid.at(6, 1000 - 63, 1000 - 63), 1.0f);
  EXPECT_EQ(grid.at(6, 1000 - 64, 1000), 0.0f);
  EXPECT_EQ(grid.at(0, 1001, 1000), 0.0f);
}

}  // namespace
}  // namespace pmap::poses
