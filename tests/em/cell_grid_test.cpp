#include "pmap/em/cell_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "pmap/em/cell_key.h"

namespace pmap::em {
namespace {

// The rectangle [0, 2 half_u] x [0, 2 half_v] of the plane z = 0.
Rectangle cornerBox(double half_u, double half_v) {
  Rectangle r;
  r.centre = {half_u, half_v, 0.0};
  r.half_u = half_u;
  r.half_v = half_v;
  return r;
}

std::vector<std::int32_t> allOf(std::size_t n) {
  std::vector<std::int32_t> v(n);
  for (std::size_t i = 0; i < n; ++i) {
    v[i] = static_cast<std::int32_t>(i);
  }
  return v;
}

TEST(CellGrid, CellsAreTheOccupiedOnesInRowMajorOrder) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> x(0.0, 4.0), y(0.0, 3.0);
  std::vector<Eigen::Vector3d> pts;
  for (int k = 0; k < 500; ++k) {
    pts.emplace_back(x(rng), y(rng), 0.0);
  }
  const CellGrid g = gridOf(pts, allOf(pts.size()), cornerBox(2.0, 1.5), 0.25);
  EXPECT_EQ(g.cols, 16);
  EXPECT_EQ(g.rows, 12);
  EXPECT_TRUE(std::is_sorted(g.cells.begin(), g.cells.end()));
  EXPECT_EQ(std::adjacent_find(g.cells.begin(), g.cells.end()), g.cells.end());
  ASSERT_EQ(g.cell_of.size(), pts.size());
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const GridCell& c = g.cells[static_cast<std::size_t>(g.cell_of[k])];
    EXPECT_EQ(c.col, static_cast<std::int64_t>(pts[k].x() / 0.25));
    EXPECT_EQ(c.row, static_cast<std::int64_t>(pts[k].y() / 0.25));
    EXPECT_EQ(g.find(c.row, c.col), g.cell_of[k]);
  }
  EXPECT_EQ(g.find(-1, 0), -1);
  EXPECT_EQ(g.find(0, 16), -1);
}

TEST(CellGrid, MembersBeyondTheRectangleCountInItsBorderCells) {
  const std::vector<Eigen::Vector3d> pts = {{-5, -5, 0}, {9, 9, 0}, {1, 1, 0}};
  const CellGrid g = gridOf(pts, allOf(3), cornerBox(1.0, 1.0), 0.5);
  ASSERT_EQ(g.cells.size(), 3u);
  EXPECT_EQ(g.cells[static_cast<std::size_t>(g.cell_of[0])], (GridCell{0, 0}));
  EXPECT_EQ(g.cells[static_cast<std::size_t>(g.cell_of[1])], (GridCell{3, 3}));
  EXPECT_EQ(g.cells[static_cast<std::size_t>(g.cell_of[2])], (GridCell{2, 2}));
}

// A rectangle stretched over astronomical distances by a few stray members
// (a mis-placed scan): the grid holds one cell per occupied cell, never
// cols x rows of them, and no cell index overflows (UBSan build).
TEST(CellGrid, Item12_CellGridMemoryFollowsPoints) {
  for (const double far_m : {1e7, 1e9, 1e12, 1e15}) {
    SCOPED_TRACE(far_m);
    std::vector<Eigen::Vector3d> pts;
    for (int k = 0; k < 200; ++k) {
      pts.emplace_back(0.01 * k, 0.02 * (k % 50), 0.0);
    }
    pts.emplace_back(far_m, 0.5, 0.0);
    pts.emplace_back(far_m, far_m, 0.0);
    pts.emplace_back(0.3, far_m, 0.0);
    const CellGrid g = gridOf(pts, allOf(pts.size()), cornerBox(far_m / 2, far_m / 2), 0.1);
    EXPECT_EQ(g.cols, std::min(kMaxCellCoord, static_cast<std::int64_t>(std::ceil(far_m / 0.1))));
    EXPECT_EQ(g.rows, g.cols);
    EXPECT_LE(g.cells.size(), pts.size());
    EXPECT_EQ(g.cell_of.size(), pts.size());
    EXPECT_EQ(g.cells.back().row, g.rows - 1);
    EXPECT_EQ(g.cells.back().col, g.cols - 1);
  }
}

TEST(CellGrid, Item12_NonFiniteOrHugeRectanglesGiveValidCells) {
  const std::vector<Eigen::Vector3d> pts = {{0, 0, 0}, {1e300, -1e300, 0}, {2, 1, 0}};
  for (const double half : {std::numeric_limits<double>::quiet_NaN(),
                            std::numeric_limits<double>::infinity(), 1e300, 0.0, -1.0}) {
    SCOPED_TRACE(half);
    const CellGrid g = gridOf(pts, allOf(3), cornerBox(half, half), 0.1);
    EXPECT_GE(g.cols, 1);
    EXPECT_LE(g.cols, kMaxCellCoord);
    EXPECT_LE(g.cells.size(), 3u);
    for (const GridCell& c : g.cells) {
      EXPECT_TRUE(c.col >= 0 && c.col < g.cols && c.row >= 0 && c.row < g.rows);
    }
  }
}

TEST(CellGrid, PartitionFollowsTheCellFlags) {
  std::vector<Eigen::Vector3d> pts(10, Eigen::Vector3d::Zero());
  pts[4] = {0.1, 0.1, 0};
  pts[7] = {1.9, 0.1, 0};
  pts[9] = {0.2, 0.1, 0};
  const CellGrid g = gridOf(pts, {4, 7, 9}, cornerBox(1.0, 1.0), 1.0);
  ASSERT_EQ(g.cells.size(), 2u);
  const SplitProposal p = partition({4, 7, 9}, g.cell_of, {1, 0});
  EXPECT_EQ(p.part_a, (std::vector<std::int32_t>{4, 9}));
  EXPECT_EQ(p.part_b, (std::vector<std::int32_t>{7}));
}

TEST(CellKey, Item12_CoordinatesAreClampedAndKeysExactNearTheOrigin) {
  EXPECT_EQ(cellCoord(-0.5), -1);
  EXPECT_EQ(cellCoord(2.99), 2);
  EXPECT_EQ(cellCoord(1e300), kMaxCellCoord);
  EXPECT_EQ(cellCoord(-std::numeric_limits<double>::infinity()), -kMaxCellCoord);
  EXPECT_EQ(cellCoord(std::numeric_limits<double>::quiet_NaN()), 0);
  EXPECT_EQ(clampedCell(-3.0, 10), 0);
  EXPECT_EQ(clampedCell(9.5, 10), 9);
  EXPECT_EQ(clampedCell(1e300, 10), 9);
  EXPECT_EQ(cellCount(0.0), 1);
  EXPECT_EQ(cellCount(2.5), 3);
  EXPECT_EQ(cellCount(1e300), kMaxCellCoord);
  // Within +-2^20 cells every cell has its own key.
  std::vector<std::int64_t> keys;
  for (const std::int64_t x : {-(1 << 20), -1, 0, 1, (1 << 20) - 1}) {
    for (const std::int64_t y : {-(1 << 20), 0, (1 << 20) - 1}) {
      for (const std::int64_t z : {-7, 0, 7}) {
        keys.push_back(cellKey(x, y, z));
      }
    }
  }
  std::sort(keys.begin(), keys.end());
  EXPECT_EQ(std::adjacent_find(keys.begin(), keys.end()), keys.end());
  // Far cells (1e12 m at 0.1 m cells) get keys of their own too, in practice.
  EXPECT_NE(cellKey(10'000'000'000'000, 0, 0), cellKey(-10'000'000'000'000, 0, 0));
  EXPECT_NE(cellKey(kMaxCellCoord, 0, 0), cellKey(0, 0, 0));
}

TEST(CellKey, Item12_TheFastKeyOfAPointIsTheKeyOfItsCell) {
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const double scale : {1.0, 1e3, 1e5, 1.048576e5, 1e6, 1e9, 1e12, 1e300}) {
    for (int k = 0; k < 200; ++k) {
      const Eigen::Vector3d p(scale * unit(rng), scale * unit(rng), unit(rng));
      for (const double cell : {0.1, 1.0}) {
        const Eigen::Matrix<std::int64_t, 3, 1> c = cellOf(p, cell);
        EXPECT_EQ(cellKeyOf(p, cell), cellKey(c.x(), c.y(), c.z())) << p.transpose();
      }
    }
  }
  const Eigen::Vector3d nan(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  EXPECT_EQ(cellKeyOf(nan, 1.0), cellKey(0, 0, 0));
}

}  // namespace
}  // namespace pmap::em
