// Spatial blocks (spatial_blocks.h): a partition of the points into blocks
// of bounded size, each with the others' points within its margin, the same
// for the same input; a block's own measurements with their neighbours.
#include "pmap/em/spatial_blocks.h"

#include <gtest/gtest.h>

#include <random>

#include "em_test_worlds.h"

namespace pmap::em {
namespace {

// Random points on a 40 m x 6 m floor plan (z 0-3 m).
std::vector<Eigen::Vector3d> floorPlan(std::size_t n) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> x(0.0, 40.0), y(0.0, 6.0), z(0.0, 3.0);
  std::vector<Eigen::Vector3d> out;
  for (std::size_t i = 0; i < n; ++i) {
    out.emplace_back(x(rng), y(rng), z(rng));
  }
  return out;
}

TEST(SpatialBlocks, OwnPointsPartitionTheInputInBoundedBlocks) {
  const std::vector<Eigen::Vector3d> points = floorPlan(10000);
  const std::vector<SpatialBlock> blocks = cutIntoBlocks(points, 1200, 0.5);
  ASSERT_EQ(blocks.size(), blockCount(points.size(), 1200));
  EXPECT_EQ(blocks.size(), 16u);  // 10000 -> 5000 -> 2500 -> 1250 -> 625
  std::vector<int> owned(points.size(), 0);
  for (const SpatialBlock& b : blocks) {
    ASSERT_LE(b.core, 1200u);
    ASSERT_GT(b.core, 0u);
    EXPECT_TRUE(std::is_sorted(b.index.begin(), b.index.begin() + b.core));
    for (std::size_t k = 0; k < b.index.size(); ++k) {
      const Eigen::Vector3d& p = points[static_cast<std::size_t>(b.index[k])];
      if (k < b.core) {
        ++owned[static_cast<std::size_t>(b.index[k])];
        EXPECT_TRUE((p.head<2>().array() >= b.lo.array()).all());
        EXPECT_TRUE((p.head<2>().array() <= b.hi.array()).all());
      } else {  // the margin: within 0.5 m of the box, not inside it
        EXPECT_TRUE((p.head<2>().array() >= b.lo.array() - 0.5).all());
        EXPECT_TRUE((p.head<2>().array() <= b.hi.array() + 0.5).all());
      }
    }
  }
  for (const int o : owned) {
    ASSERT_EQ(o, 1);
  }
}

TEST(SpatialBlocks, CutsAlongTheLongerSideAndAreDeterministic) {
  const std::vector<Eigen::Vector3d> points = floorPlan(4000);
  const std::vector<SpatialBlock> blocks = cutIntoBlocks(points, 1000, 1.0);
  ASSERT_EQ(blocks.size(), 4u);
  for (const SpatialBlock& b : blocks) {
    EXPECT_NEAR(b.hi.y() - b.lo.y(), 6.0, 0.1);  // 40 m x 6 m: every cut across x
    EXPECT_NEAR(b.hi.x() - b.lo.x(), 10.0, 1.5);
    EXPECT_GT(b.index.size(), b.core);  // each has a neighbour within 1 m
  }
  const std::vector<SpatialBlock> again = cutIntoBlocks(points, 1000, 1.0);
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    EXPECT_EQ(again[b].index, blocks[b].index);
    EXPECT_EQ(again[b].core, blocks[b].core);
  }
}

TEST(SpatialBlocks, FewPointsOrNoMarginGiveOneBlockOrNoMargin) {
  const std::vector<Eigen::Vector3d> points = floorPlan(500);
  const std::vector<SpatialBlock> one = cutIntoBlocks(points, 500, 1.0);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].core, 500u);
  EXPECT_EQ(one[0].index.size(), 500u);
  EXPECT_EQ(blockCount(500, 500), 1u);
  EXPECT_EQ(blockCount(501, 500), 2u);
  for (const SpatialBlock& b : cutIntoBlocks(points, 100, 0.0)) {
    EXPECT_EQ(b.index.size(), b.core);
  }
  EXPECT_TRUE(cutIntoBlocks({}, 100, 1.0).empty());
}

TEST(SpatialBlocks, ABlocksInputKeepsItsOwnNeighboursOnly) {
  testing::Cloud c;
  std::mt19937_64 rng(2);
  testing::addPlane(c, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 8.0, 2.0, 0.05, 0.01, rng);
  const Neighbours all = c.neighbours();
  const std::vector<SpatialBlock> blocks = cutIntoBlocks(c.points, (c.points.size() + 1) / 2, 0.2);
  ASSERT_EQ(blocks.size(), 2u);
  const SpatialBlock& b = blocks[0];
  const BlockInput in = blockInput(b, c.points, all, c.rows);
  ASSERT_EQ(in.points.size(), b.index.size());
  ASSERT_EQ(in.rows.size(), b.index.size());
  std::size_t cut = 0;
  for (std::size_t k = 0; k < b.index.size(); ++k) {
    const auto i = static_cast<std::size_t>(b.index[k]);
    EXPECT_EQ(in.points[k], c.points[i]);
    EXPECT_EQ(in.rows[k], c.rows[i]);
    for (int m = 0; m < 4; ++m) {
      const std::int32_t local = in.neighbours[k][static_cast<std::size_t>(m)];
      const std::int32_t global = all[i][static_cast<std::size_t>(m)];
      if (local >= 0) {
        EXPECT_EQ(b.index[static_cast<std::size_t>(local)], global);
      } else {
        cut += global >= 0 ? 1 : 0;
      }
    }
  }
  EXPECT_GT(cut, 0u);  // the block's edge: neighbours past its margin are gone
  EXPECT_TRUE(blockInput(b, c.points, all, {}).rows.empty());
}

}  // namespace
}  // namespace pmap::em
