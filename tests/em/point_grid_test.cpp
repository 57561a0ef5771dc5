#include "pmap/em/point_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace pmap::em {
namespace {

std::vector<Eigen::Vector3d> randomCloud(std::mt19937_64& rng, int n, const Eigen::Vector3d& at,
                                         double size) {
  std::uniform_real_distribution<double> u(-size, size);
  std::vector<Eigen::Vector3d> pts;
  for (int k = 0; k < n; ++k) {
    pts.push_back(at + Eigen::Vector3d(u(rng), u(rng), u(rng)));
  }
  return pts;
}

std::vector<std::int32_t> bruteWithin(const std::vector<Eigen::Vector3d>& pts,
                                      const Eigen::Vector3d& c, double r) {
  std::vector<std::int32_t> out;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if ((pts[i] - c).squaredNorm() <= r * r) {
      out.push_back(static_cast<std::int32_t>(i));
    }
  }
  return out;
}

TEST(PointGrid, EmptyGridFindsNothing) {
  const std::vector<Eigen::Vector3d> none;
  const PointGrid g(none, 0.5);
  EXPECT_TRUE(g.within({0, 0, 0}, 10.0).empty());
  EXPECT_TRUE(g.inBox({-1, -1, -1}, {1, 1, 1}).empty());
  EXPECT_DOUBLE_EQ(g.cell(), 0.5);
}

TEST(PointGrid, WithinMatchesBruteForce) {
  std::mt19937_64 rng(1);
  for (const Eigen::Vector3d& at : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(-3.3, 7.1, -0.4),
                                    Eigen::Vector3d(1e5, -1e5, 50)}) {
    const auto pts = randomCloud(rng, 2000, at, 2.0);
    const PointGrid g(pts, 0.3);
    for (int q = 0; q < 200; ++q) {
      const Eigen::Vector3d c = randomCloud(rng, 1, at, 2.5)[0];
      const double r = 0.05 + 0.01 * (q % 100);
      EXPECT_EQ(g.within(c, r), bruteWithin(pts, c, r));
    }
  }
}

TEST(PointGrid, WithinIsInclusiveAndHandlesDuplicatesAndZeroRadius) {
  const std::vector<Eigen::Vector3d> pts = {{0, 0, 0}, {1, 0, 0}, {0, 0, 0}, {0.5, 0, 0}};
  const PointGrid g(pts, 0.25);
  EXPECT_EQ(g.within({0, 0, 0}, 0.0), (std::vector<std::int32_t>{0, 2}));
  EXPECT_EQ(g.within({0, 0, 0}, 0.5), (std::vector<std::int32_t>{0, 2, 3}));
  EXPECT_EQ(g.within({0, 0, 0}, 1.0), (std::vector<std::int32_t>{0, 1, 2, 3}));
}

TEST(PointGrid, InBoxIsAnAscendingSupersetOfThePointsInTheBox) {
  std::mt19937_64 rng(2);
  const auto pts = randomCloud(rng, 3000, {2, 2, 2}, 3.0);
  const PointGrid g(pts, 0.4);
  std::uniform_real_distribution<double> u(-2.0, 6.0);
  for (int q = 0; q < 100; ++q) {
    Eigen::Vector3d lo(u(rng), u(rng), u(rng));
    Eigen::Vector3d hi = lo + Eigen::Vector3d::Constant(0.1 + 0.05 * (q % 40));
    const auto got = g.inBox(lo, hi);
    EXPECT_TRUE(std::is_sorted(got.begin(), got.end()));
    EXPECT_EQ(std::adjacent_find(got.begin(), got.end()), got.end());
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const bool inside =
          (pts[i].array() >= lo.array()).all() && (pts[i].array() <= hi.array()).all();
      if (inside) {
        EXPECT_TRUE(std::binary_search(got.begin(), got.end(), static_cast<std::int32_t>(i)));
      }
    }
    // Superset only up to a cell: nothing farther than a cell from the box.
    for (const std::int32_t i : got) {
      const Eigen::Vector3d p = pts[i];
      EXPECT_TRUE((p.array() >= lo.array() - 0.4).all() && (p.array() <= hi.array() + 0.4).all());
    }
  }
}

TEST(PointGrid, AHugeBoxReturnsEveryPointOnce) {
  std::mt19937_64 rng(3);
  const auto pts = randomCloud(rng, 500, {0, 0, 0}, 1.0);
  const PointGrid g(pts, 0.1);
  const auto got = g.inBox({-1e4, -1e4, -1e4}, {1e4, 1e4, 1e4});
  ASSERT_EQ(got.size(), pts.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i], static_cast<std::int32_t>(i));
  }
  EXPECT_EQ(g.within({0, 0, 0}, 1e4).size(), pts.size());
}

// Points spread over +-1e12 m: one cell per occupied cell (the grid never
// spans the extent), exact answers, and no cell coordinate overflow (UBSan).
TEST(PointGrid, Item12_PointGridMemoryFollowsPoints) {
  std::mt19937_64 rng(4);
  std::vector<Eigen::Vector3d> pts;
  for (const Eigen::Vector3d& at :
       {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1e12, 0, 0), Eigen::Vector3d(-1e12, 1e12, 3e9),
        Eigen::Vector3d(2.6e10, -7e11, 0), Eigen::Vector3d(1e300, 0, 0)}) {
    const auto cluster = randomCloud(rng, 100, at, 0.5);
    pts.insert(pts.end(), cluster.begin(), cluster.end());
  }
  const PointGrid g(pts, 0.1);
  EXPECT_LE(g.occupiedCells(), pts.size());
  for (std::size_t i = 0; i < pts.size(); i += 7) {
    EXPECT_EQ(g.within(pts[i], 0.3), bruteWithin(pts, pts[i], 0.3)) << i;
  }
  // A box over everything lists every point once.
  const auto all = g.inBox(Eigen::Vector3d::Constant(-1e301), Eigen::Vector3d::Constant(1e301));
  EXPECT_EQ(all.size(), pts.size());
  EXPECT_EQ(std::adjacent_find(all.begin(), all.end()), all.end());
}

}  // namespace
}  // namespace pmap::em
