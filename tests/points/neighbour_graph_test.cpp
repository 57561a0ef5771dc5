#include "pmap/points/neighbour_graph.h"

#include <gtest/gtest.h>

#include <random>

namespace pmap::points {
namespace {

// An unorganised cloud (PLY, Velodyne) of `n` points in a 1 m cube at `at`,
// on a 1/4096 m lattice: shifted by up to 2^40 m, differences stay exact.
input::StructureScan cloudAt(std::int64_t index, const Eigen::Vector3d& at, int n,
                             std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  input::StructureScan s;
  s.index = index;
  s.label = "CLOUD";
  s.cols = n;
  s.organised = false;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d q(u(rng), u(rng), u(rng));
    s.points.push_back(at + (q * 4096.0).array().round().matrix() / 4096.0);
    s.beams.push_back(i);
  }
  return s;
}

TEST(NeighbourGraph, ScansOfOneSensorAreLinkedBeamByBeamAndScanByScan) {
  PointMap map;
  for (int k = 0; k < 3; ++k) {
    input::StructureScan s;
    s.index = k;
    s.label = "V";
    s.cols = 4;
    for (int b = 0; b < 4; ++b) {
      s.points.emplace_back(0.1 * k, 0.05 * b, 1.0);
      s.beams.push_back(b);
    }
    map.addScan(s, {});
  }
  const NeighbourGraph g = neighbourGraph(map, 0.25);
  ASSERT_EQ(g.neighbours.size(), 12u);
  EXPECT_EQ(g.rows, (std::vector<std::int32_t>{0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2}));
  EXPECT_EQ(g.neighbours[5], (std::array<std::int32_t, 4>{4, 6, 1, 9}));
}

// Clusters of a cloud 1e9 and 1e12 m apart (a mis-placed scan): each
// cluster's neighbours are its own, as if it were alone, and the grid behind
// them holds the points' cells, not the extent's (no overflow, UBSan build).
TEST(NeighbourGraph, Item12_CloudClustersAstronomicallyApartAreLinkedAlone) {
  std::mt19937_64 rng(5);
  PointMap alone, spread;
  const input::StructureScan near = cloudAt(0, {0, 0, 0}, 300, rng);
  alone.addScan(near, {});
  input::StructureScan all = near;
  for (const double far_m : {0x1p30, -0x1p40}) {  // 1.07e9 m, -1.1e12 m
    for (int i = 0; i < 300; ++i) {
      all.points.push_back(near.points[static_cast<std::size_t>(i)] +
                           Eigen::Vector3d(far_m, 0.0, far_m));
      all.beams.push_back(static_cast<std::int32_t>(all.beams.size()));
    }
  }
  all.cols = static_cast<int>(all.points.size());
  spread.addScan(all, {});
  const NeighbourGraph one = neighbourGraph(alone, 0.25);
  const NeighbourGraph g = neighbourGraph(spread, 0.25);
  EXPECT_TRUE(g.rows.empty());
  ASSERT_EQ(g.neighbours.size(), 900u);
  for (std::size_t c = 0; c < 3; ++c) {
    for (std::size_t i = 0; i < 300; ++i) {
      for (std::size_t m = 0; m < 4; ++m) {
        const std::int32_t n = one.neighbours[i][m];
        EXPECT_EQ(g.neighbours[c * 300 + i][m],
                  n < 0 ? -1 : n + static_cast<std::int32_t>(c * 300));
      }
    }
  }
}

}  // namespace
}  // namespace pmap::points
