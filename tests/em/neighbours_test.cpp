#include "pmap/em/neighbours.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace pmap::em {
namespace {

using Slots = std::array<std::int32_t, 4>;

TEST(GridNeighbours, EmptyInputGivesNoNeighbours) {
  EXPECT_TRUE(gridNeighbours({}).empty());
}

TEST(GridNeighbours, OnAGridEachPointSeesItsFourGridNeighbours) {
  std::vector<GridKey> keys;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) {
      keys.push_back({0, r, c});  // index r * 4 + c
    }
  }
  const Neighbours n = gridNeighbours(keys);
  ASSERT_EQ(n.size(), 12u);
  EXPECT_EQ(n[5], (Slots{4, 6, 1, 9}));      // interior: {prev col, next col, prev row, next row}
  EXPECT_EQ(n[0], (Slots{-1, 1, -1, 4}));    // corner
  EXPECT_EQ(n[11], (Slots{10, -1, 7, -1}));  // opposite corner
}

TEST(GridNeighbours, NeighboursAreSymmetric) {
  std::vector<GridKey> keys;
  std::mt19937_64 rng(3);
  for (int r = 0; r < 20; ++r) {
    for (int c = 0; c < 20; ++c) {
      if (rng() % 4 != 0) {  // a grid with holes, in random order below
        keys.push_back({static_cast<std::int32_t>(rng() % 2), r, c});
      }
    }
  }
  std::shuffle(keys.begin(), keys.end(), rng);
  const Neighbours n = gridNeighbours(keys);
  const int opposite[4] = {1, 0, 3, 2};
  for (std::size_t i = 0; i < n.size(); ++i) {
    for (int s = 0; s < 4; ++s) {
      const std::int32_t j = n[i][s];
      if (j < 0) {
        continue;
      }
      EXPECT_EQ(n[j][opposite[s]], static_cast<std::int32_t>(i));
      EXPECT_EQ(keys[j].group, keys[i].group);
      EXPECT_EQ(std::abs(keys[j].row - keys[i].row) + std::abs(keys[j].col - keys[i].col), 1);
    }
  }
}

TEST(GridNeighbours, GroupsAreSeparateAndHolesHaveNoNeighbour) {
  const std::vector<GridKey> keys = {{0, 0, 0}, {1, 0, 1}, {0, 0, 2}, {0, 1, 0}};
  const Neighbours n = gridNeighbours(keys);
  EXPECT_EQ(n[0], (Slots{-1, -1, -1, 3}));   // col 1 of group 0 is a hole
  EXPECT_EQ(n[1], (Slots{-1, -1, -1, -1}));  // alone in group 1
  EXPECT_EQ(n[2], (Slots{-1, -1, -1, -1}));
  EXPECT_EQ(n[3], (Slots{-1, -1, 0, -1}));
}

TEST(GridNeighbours, DuplicateKeysFirstPointWins) {
  const std::vector<GridKey> keys = {{0, 0, 0}, {0, 0, 1}, {0, 0, 1}};
  const Neighbours n = gridNeighbours(keys);
  EXPECT_EQ(n[0][1], 1);
  EXPECT_EQ(n[2][0], 0);  // the duplicate still sees its neighbours
}

// Bug (libs/em/src/neighbours.cpp, gridNeighbours via packGridKey, formerly
// packKey): the group is packed into 16 bits (group & 0xFFFF), so groups 0
// and 65536 share keys. A range-image data set gives every frame its own
// group (libs/points/src/neighbour_graph.cpp), so from frame 65536 on, pixels
// are linked to pixels of frame 0 (and the later frame's own keys are dropped
// as "duplicates"). Neighbours must stay within their group (header:
// "Neighbours on the same group").
TEST(GridNeighbours, GroupsBeyond16BitsStaySeparate) {
  const std::vector<GridKey> keys = {{0, 0, 0}, {0, 0, 1}, {65536, 0, 0}, {65536, 0, 1}};
  const Neighbours n = gridNeighbours(keys);
  EXPECT_EQ(n[2][1], 3);
  EXPECT_EQ(n[3][0], 2);
}

TEST(NearestNeighbours, EmptyAndSinglePointHaveNoNeighbours) {
  EXPECT_TRUE(nearestNeighbours({}, 0.5).empty());
  const Neighbours n = nearestNeighbours({{1, 2, 3}}, 0.5);
  ASSERT_EQ(n.size(), 1u);
  EXPECT_EQ(n[0], (Slots{-1, -1, -1, -1}));
}

// The 4 nearest within the radius, by brute force, ties by index.
void expectBruteForce(const std::vector<Eigen::Vector3d>& pts, double radius) {
  const Neighbours n = nearestNeighbours(pts, radius);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    std::vector<std::pair<double, std::int32_t>> all;
    for (std::size_t j = 0; j < pts.size(); ++j) {
      const double d2 = (pts[j] - pts[i]).squaredNorm();
      if (j != i && d2 <= radius * radius) {
        all.emplace_back(d2, static_cast<std::int32_t>(j));
      }
    }
    std::sort(all.begin(), all.end());
    for (std::size_t s = 0; s < 4; ++s) {
      ASSERT_EQ(n[i][s], s < all.size() ? all[s].second : -1) << "point " << i;
    }
  }
}

TEST(NearestNeighbours, MatchesBruteForceWithinTheRadius) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Vector3d> pts;
  for (int k = 0; k < 400; ++k) {
    pts.emplace_back(u(rng), u(rng), 0.3 * u(rng));
  }
  pts.push_back(pts[10]);  // a duplicate: distance 0
  expectBruteForce(pts, 0.2);
  const Neighbours n = nearestNeighbours(pts, 0.2);
  EXPECT_EQ(n[10][0], static_cast<std::int32_t>(pts.size() - 1));
  EXPECT_EQ(n.back()[0], 10);
}

// Dense: about 30 points within an eighth of the radius, where the search
// looks first; a sparse corner of the box makes some points search the
// whole radius. Same answer as brute force either way.
TEST(NearestNeighbours, DenseCloudsMatchBruteForceToo) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  std::vector<Eigen::Vector3d> pts;
  for (int k = 0; k < 3000; ++k) {
    pts.emplace_back(u(rng), u(rng), 0.1 * u(rng));
  }
  for (int k = 0; k < 40; ++k) {
    pts.emplace_back(0.5 + u(rng), 0.5 + u(rng), u(rng));
  }
  expectBruteForce(pts, 0.2);
  EXPECT_EQ(nearestNeighbours(pts, 0.2, 3), nearestNeighbours(pts, 0.2));  // any thread count
}

// A 2D laser's sweep through a corridor: points 1 cm apart along scan
// lines 8 cm apart, so the fourth nearest is 2 cm away and the fine grid's
// cell is the widest (half the radius); a sparse stretch of lines 20 cm
// apart, whose points find only their line within the radius; and a dense
// patch whose points all lie in one fine cell. Same answer as brute force.
TEST(NearestNeighbours, SweepLikeCloudsOfMixedDensityMatchBruteForce) {
  std::mt19937_64 rng(29);
  std::normal_distribution<double> noise(0.0, 0.002);
  std::vector<Eigen::Vector3d> pts;
  for (int line = 0; line < 12; ++line) {
    const double x = line < 8 ? 0.08 * line : 0.64 + 0.2 * (line - 7);
    for (int k = 0; k < 150; ++k) {
      pts.emplace_back(x + noise(rng), 1.0 + noise(rng), 0.01 * k);
    }
  }
  for (int k = 0; k < 60; ++k) {
    pts.emplace_back(0.3 + 0.1 * noise(rng), 0.9 + 0.1 * noise(rng), 0.7 + 0.1 * noise(rng));
  }
  expectBruteForce(pts, 0.15);
  EXPECT_EQ(nearestNeighbours(pts, 0.15, 2), nearestNeighbours(pts, 0.15));
}

TEST(NearestNeighbours, TiesAreBrokenByIndex) {
  // Four points at distance 1 from the centre and one more at distance 1.
  const std::vector<Eigen::Vector3d> pts = {{0, 0, 0}, {0, 0, 1},  {1, 0, 0},
                                            {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  const Neighbours n = nearestNeighbours(pts, 1.5);
  EXPECT_EQ(n[0], (Slots{1, 2, 3, 4}));
}

TEST(NearestNeighbours, FarFromTheOriginGivesTheSameGraph) {
  std::mt19937_64 rng(19);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Eigen::Vector3d> pts, far;
  for (int k = 0; k < 200; ++k) {
    pts.emplace_back(u(rng), u(rng), u(rng));
    far.push_back(pts.back() + Eigen::Vector3d(3e4, -2e4, 100.0));
  }
  EXPECT_EQ(nearestNeighbours(pts, 0.25), nearestNeighbours(far, 0.25));
}

// Clusters 1e9 to 1e12 m apart: neighbours within each cluster, as if it
// were alone, and a grid over the points only (no overflow, UBSan build).
TEST(NearestNeighbours, Item12_ClustersAstronomicallyApartAreMappedAlone) {
  std::mt19937_64 rng(20);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Eigen::Vector3d> near, all;
  for (int k = 0; k < 100; ++k) {  // on a 1/4096 m lattice: shifts by 2^40 m stay exact
    const Eigen::Vector3d q(u(rng), u(rng), u(rng));
    near.push_back((q * 4096.0).array().round().matrix() / 4096.0);
  }
  for (const double far_m : {0.0, 0x1p30, -0x1p40}) {  // 0, 1.07e9 m, -1.1e12 m
    for (const Eigen::Vector3d& p : near) {
      all.push_back(p + Eigen::Vector3d(far_m, 0.0, 0.0));
    }
  }
  const Neighbours one = nearestNeighbours(near, 0.25);
  const Neighbours n = nearestNeighbours(all, 0.25);
  for (std::size_t c = 0; c < 3; ++c) {
    for (std::size_t i = 0; i < near.size(); ++i) {
      for (std::size_t m = 0; m < 4; ++m) {
        const std::int32_t expected =
            one[i][m] < 0 ? -1 : one[i][m] + static_cast<std::int32_t>(c * near.size());
        EXPECT_EQ(n[c * near.size() + i][m], expected);
      }
    }
  }
}

}  // namespace
}  // namespace pmap::em
