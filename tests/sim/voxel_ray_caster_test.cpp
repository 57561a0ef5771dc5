#include "pmap/sim/voxel_ray_caster.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace pmap::sim {
namespace {

/// A closed box room: free inside = voxels [0, nx) x [0, ny) x [0, nz).
VoxelWorld boxRoom(double res, int nx, int ny, int nz) {
  std::vector<VoxelWorld::Block> blocks;
  for (int i = -1; i <= nx; ++i) {
    for (int j = -1; j <= ny; ++j) {
      for (int k = -1; k <= nz; ++k) {
        if (i < 0 || i >= nx || j < 0 || j >= ny || k < 0 || k >= nz) {
          blocks.push_back({Eigen::Vector3i(i, j, k), 1});
        }
      }
    }
  }
  return VoxelWorld(res, blocks);
}

double rangeOf(const VoxelRayCaster& caster, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
               double t_max = 30.0) {
  const auto hit = caster.cast(o, d.normalized(), t_max);
  return hit ? hit->t : -1.0;
}

TEST(VoxelRayCaster, BoxRoomDistancesToTheFaces) {
  const VoxelWorld room = boxRoom(0.1, 60, 40, 25);  // 6 x 4 x 2.5 m inside
  const VoxelRayCaster caster(room);
  const Eigen::Vector3d o(2.2, 1.5, 0.4);
  EXPECT_NEAR(rangeOf(caster, o, {1, 0, 0}), 3.8, 1e-9);
  EXPECT_NEAR(rangeOf(caster, o, {-1, 0, 0}), 2.2, 1e-9);
  EXPECT_NEAR(rangeOf(caster, o, {0, 1, 0}), 2.5, 1e-9);
  EXPECT_NEAR(rangeOf(caster, o, {0, -1, 0}), 1.5, 1e-9);
  EXPECT_NEAR(rangeOf(caster, o, {0, 0, 1}), 2.1, 1e-9);
  EXPECT_NEAR(rangeOf(caster, o, {0, 0, -1}), 0.4, 1e-9);
  EXPECT_NEAR(rangeOf(caster, o, {1, 1, 0}), 2.5 * std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(rangeOf(caster, o, {-1, -1, -1}), 0.4 * std::sqrt(3.0), 1e-9);
  const auto hit = caster.cast({2.25, 1.55, 0.45}, Eigen::Vector3d(1, 0, 0), 30.0);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->voxel, Eigen::Vector3i(60, 15, 4));
  EXPECT_NEAR(hit->t, 3.75, 1e-9);
}

TEST(VoxelRayCaster, MaxRangeOriginInsideAndEmptyWorld) {
  const VoxelWorld room = boxRoom(0.1, 60, 40, 25);
  const VoxelRayCaster caster(room);
  EXPECT_FALSE(caster.cast({2.2, 1.5, 0.4}, {1, 0, 0}, 3.8 - 1e-9));
  EXPECT_TRUE(caster.cast({2.2, 1.5, 0.4}, {1, 0, 0}, 3.8 + 1e-9));
  const auto inside = caster.cast({-0.05, 1.0, 1.0}, {1, 0, 0}, 5.0);
  ASSERT_TRUE(inside);
  EXPECT_EQ(inside->t, 0.0);
  // From outside the room, the first wall met from outside.
  EXPECT_NEAR(rangeOf(caster, {-1.0, 1.0, 1.0}, {1, 0, 0}), 0.9, 1e-9);
  EXPECT_FALSE(caster.cast({-1.0, 1.0, 1.0}, {-1, 0, 0}, 100.0));
  const VoxelWorld empty(0.1, {});
  EXPECT_FALSE(VoxelRayCaster(empty).cast({0, 0, 0}, {1, 0, 0}, 10.0));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(caster.cast({nan, 0, 0}, {1, 0, 0}, 10.0));
}

/// The reference: every occupied voxel's cube against the ray (slab method).
double bruteForce(const std::vector<Eigen::Vector3i>& voxels, double res, const Eigen::Vector3d& o,
                  const Eigen::Vector3d& d, double t_max) {
  double best = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3i& v : voxels) {
    double t0 = 0.0, t1 = t_max;
    for (int a = 0; a < 3; ++a) {
      const double lo = v[a] * res, hi = (v[a] + 1) * res;
      if (d[a] == 0.0) {
        if (o[a] < lo || o[a] >= hi) {
          t0 = 1.0, t1 = 0.0;
        }
        continue;
      }
      const double ta = (lo - o[a]) / d[a], tb = (hi - o[a]) / d[a];
      t0 = std::max(t0, std::min(ta, tb));
      t1 = std::min(t1, std::max(ta, tb));
    }
    if (t0 <= t1) {
      best = std::min(best, t0);
    }
  }
  return best;
}

TEST(VoxelRayCaster, AgreesWithBruteForceOnRandomVoxels) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> cell(-10, 9);
  std::uniform_real_distribution<double> coord(-1.3, 1.3), unit(-1.0, 1.0), range(0.0, 4.0);
  std::vector<Eigen::Vector3i> voxels;
  std::vector<VoxelWorld::Block> blocks;
  for (int n = 0; n < 150; ++n) {
    voxels.emplace_back(cell(rng), cell(rng), cell(rng));
    blocks.push_back({voxels.back(), 1});
  }
  const double res = 0.125;
  const VoxelWorld world(res, blocks);
  const VoxelRayCaster caster(world);
  int hits = 0;
  for (int n = 0; n < 3000; ++n) {
    const Eigen::Vector3d o(coord(rng), coord(rng), coord(rng));
    Eigen::Vector3d d(unit(rng), unit(rng), unit(rng));
    if (n % 10 == 0) {
      d[n % 3] = 0.0;  // rays parallel to a coordinate plane
    }
    if (d.norm() < 1e-3) {
      continue;
    }
    d.normalize();
    const double t_max = range(rng);
    const double expected = bruteForce(voxels, res, o, d, t_max);
    const auto hit = caster.cast(o, d, t_max);
    ASSERT_EQ(hit.has_value(), std::isfinite(expected)) << "ray " << n;
    if (hit) {
      ++hits;
      EXPECT_NEAR(hit->t, expected, 1e-9) << "ray " << n;
      EXPECT_TRUE(world.occupied(hit->voxel));
    }
  }
  EXPECT_GT(hits, 300);
}

}  // namespace
}  // namespace pmap::sim
