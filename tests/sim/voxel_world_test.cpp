#include "pmap/sim/voxel_world.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "pmap/common/error.h"
#include "sim_test_support.h"
#include "voxel_test_support.h"

namespace pmap::sim {
namespace {

namespace fs = std::filesystem;

const fs::path kGeb079 = "/usr/share/doc/liboctomap-dev/examples/data/geb079.bt";

OctomapSpec specFor(const fs::path& file) {
  OctomapSpec spec;
  spec.where = "octomap";
  spec.file = file;
  spec.file_as_written = file.string();
  return spec;
}

std::string loadError(const OctomapSpec& spec) {
  try {
    loadVoxelWorld(spec);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(VoxelWorld, BlocksBecomeVoxels) {
  const VoxelWorld w(0.1, {{Eigen::Vector3i(-3, 2, 0), 1},
                           {Eigen::Vector3i(4, 4, 4), 4},
                           {Eigen::Vector3i(-2, -2, -2), 2}});
  EXPECT_EQ(w.occupiedVoxels(), 1u + 64u + 8u);
  EXPECT_TRUE(w.occupied({-3, 2, 0}));
  EXPECT_FALSE(w.occupied({-3, 2, 1}));
  EXPECT_TRUE(w.occupied({4, 4, 4}));
  EXPECT_TRUE(w.occupied({7, 7, 7}));
  EXPECT_FALSE(w.occupied({8, 7, 7}));
  EXPECT_TRUE(w.occupied({-1, -1, -1}));
  EXPECT_FALSE(w.occupied({-3, -2, -2}));
  EXPECT_EQ(w.minIndex(), Eigen::Vector3i(-3, -2, -2));
  EXPECT_EQ(w.maxIndex(), Eigen::Vector3i(7, 7, 7));
  EXPECT_FALSE(w.occupied({40000, 0, 0}));  // outside the key range
  EXPECT_EQ(w.voxelOf({-0.05, 0.0, 0.1999}), Eigen::Vector3i(-1, 0, 1));
  EXPECT_TRUE(w.voxelCentre({-1, 0, 2}).isApprox(Eigen::Vector3d(-0.05, 0.05, 0.25)));
}

TEST(VoxelWorld, RefusesBadBlocks) {
  EXPECT_THROW(VoxelWorld(0.0, {}), std::invalid_argument);
  EXPECT_THROW(VoxelWorld(0.1, {{Eigen::Vector3i::Zero(), 3}}), std::invalid_argument);
  EXPECT_THROW(VoxelWorld(0.1, {{Eigen::Vector3i(1, 0, 0), 2}}), std::invalid_argument);
  EXPECT_THROW(VoxelWorld(0.1, {{Eigen::Vector3i(32767, 0, 0), 2}}), std::invalid_argument);
  EXPECT_TRUE(VoxelWorld(0.1, {}).empty());
}

// OctoMap writes the tree (pruning the aligned solid block into coarser
// leaves); every occupied voxel comes back, and nothing else.
TEST(VoxelWorld, LoadsWhatOctoMapWrote) {
  const fs::path dir = test::freshDir("voxel_world_load");
  const Eigen::Vector3i lo(0, 0, 0), hi(20, 12, 10), corner(8, 4, 0);
  const std::size_t written = test::writeBoxRoomTree(dir / "room.bt", 0.1, lo, hi, corner, 4);
  const VoxelWorld w = loadVoxelWorld(specFor(dir / "room.bt"));
  EXPECT_EQ(w.occupiedVoxels(), written);
  EXPECT_DOUBLE_EQ(w.resolution_m(), 0.1);
  EXPECT_EQ(w.minIndex(), Eigen::Vector3i(-1, -1, -1));
  EXPECT_EQ(w.maxIndex(), Eigen::Vector3i(20, 12, 10));
  EXPECT_LT(w.info().occupied_leaves, written);  // the block was pruned
  EXPECT_EQ(w.info().tree_type, "OcTree");
  EXPECT_EQ(w.info().bytes, fs::file_size(dir / "room.bt"));
  for (int i = -1; i <= 20; ++i) {
    for (int j = -1; j <= 12; ++j) {
      for (int k = -1; k <= 10; ++k) {
        const bool shell = i < 0 || i >= 20 || j < 0 || j >= 12 || k < 0 || k >= 10;
        const bool block = i >= 8 && i < 12 && j >= 4 && j < 8 && k >= 0 && k < 4;
        ASSERT_EQ(w.occupied({i, j, k}), shell || block) << i << " " << j << " " << k;
      }
    }
  }
}

TEST(VoxelWorld, MissingUnreadableAndOversizedFiles) {
  const fs::path dir = test::freshDir("voxel_world_files");
  EXPECT_NE(loadError(specFor(dir / "none.bt")).find("none.bt: OctoMap tree not found"),
            std::string::npos);
  EXPECT_NE(loadError(specFor(dir)).find("not a regular file"), std::string::npos);
  test::writeBoxRoomTree(dir / "room.bt", 0.1, {0, 0, 0}, {10, 10, 10});
  OctomapSpec small = specFor(dir / "room.bt");
  small.max_tree_nodes = 100;
  EXPECT_NE(loadError(small).find("more than max_tree_nodes (100)"), std::string::npos);
  small.max_tree_nodes = 1000000;
  small.max_occupied_voxels = 100;
  EXPECT_NE(loadError(small).find("more than max_occupied_voxels (100)"), std::string::npos);
}

// Every cut and every flipped byte of a real file: an InputError or a tree
// whose structure checked out; OctoMap never reads damaged data.
TEST(VoxelWorld, TruncatedAndFlippedFilesNeverCrash) {
  const fs::path dir = test::freshDir("voxel_world_damage");
  test::writeBoxRoomTree(dir / "room.bt", 0.2, {0, 0, 0}, {4, 3, 3});
  const std::string bytes = test::readBytes(dir / "room.bt");
  const fs::path damaged = dir / "damaged.bt";
  int refused = 0, accepted = 0;
  for (std::size_t cut = 0; cut < bytes.size(); ++cut) {
    test::writeText(damaged, bytes.substr(0, cut));
    EXPECT_FALSE(loadError(specFor(damaged)).empty()) << "cut at " << cut;
  }
  for (std::size_t at = 0; at < bytes.size(); ++at) {
    std::string flipped = bytes;
    flipped[at] = static_cast<char>(flipped[at] ^ 0x5a);
    test::writeText(damaged, flipped);
    (loadError(specFor(damaged)).empty() ? accepted : refused) += 1;
  }
  EXPECT_GT(refused, 0);
  EXPECT_GT(accepted + refused, 0);
}

TEST(VoxelWorld, Geb079ReadsAsMapEvalReadsIt) {
  if (!fs::exists(kGeb079)) {
    GTEST_SKIP() << kGeb079 << " not installed (Debian's liboctomap-dev examples)";
  }
  const VoxelWorld w = loadVoxelWorld(specFor(kGeb079));
  EXPECT_EQ(w.occupiedVoxels(), 185673u);  // doc/evaluation.md, "Voxel ground truth"
  EXPECT_DOUBLE_EQ(w.resolution_m(), 0.08);
  EXPECT_EQ(w.info().tree_nodes, 532566u);
}

}  // namespace
}  // namespace pmap::sim
