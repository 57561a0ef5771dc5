// map-eval's voxel ground truth (voxel_evaluation.h): a wall of occupied
// voxels written as a .bt, read back, and maps scored against it.
#include "pmap/eval/voxel_evaluation.h"

#include <gtest/gtest.h>
#include <octomap/OcTree.h>

#include <fstream>

#include "pmap/common/error.h"

namespace pmap::eval {
namespace {
namespace fs = std::filesystem;

fs::path testDir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("pmap_voxel_eval_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// The voxels of a 4 m x 2 m wall in the plane x = 1.05 (the centres of the
// 10 cm voxels [1.0, 1.1) x [0, 4) x [0, 2)), written as a .bt.
fs::path writeWall(const fs::path& dir) {
  octomap::OcTree tree(0.1);
  for (double y = 0.05; y < 4.0; y += 0.1) {
    for (double z = 0.05; z < 2.0; z += 0.1) {
      tree.updateNode(octomap::point3d(1.05f, static_cast<float>(y), static_cast<float>(z)), true);
    }
  }
  tree.updateNode(octomap::point3d(3.05f, 2.05f, 1.05f), false);  // free: not ground truth
  const fs::path bt = dir / "wall.bt";
  EXPECT_TRUE(tree.writeBinary(bt.string()));
  return bt;
}

// The rectangle x = x0, y in [y0, y1], z in [0, 2] as two triangles.
std::vector<Triangle3> wallAt(double x0, double y0, double y1) {
  const Eigen::Vector3d a(x0, y0, 0), b(x0, y1, 0), c(x0, y1, 2), d(x0, y0, 2);
  return {{a, b, c}, {a, c, d}};
}

TEST(VoxelGroundTruth, ReadsTheOccupiedVoxelsOfATree) {
  const VoxelGroundTruth gt = readVoxelGroundTruth(writeWall(testDir("read")));
  EXPECT_DOUBLE_EQ(gt.resolution_m, 0.1);
  EXPECT_EQ(gt.centres.size(), 40u * 20u);  // pruned leaves expanded, the free voxel left out
  for (const Eigen::Vector3d& c : gt.centres) {
    EXPECT_NEAR(c.x(), 1.05, 1e-6);
  }
}

TEST(VoxelGroundTruth, RefusesWhatIsNotATree) {
  const fs::path dir = testDir("bad");
  EXPECT_THROW(readVoxelGroundTruth(dir / "missing.bt"), InputError);
  std::ofstream(dir / "text.bt") << "hello\n";
  EXPECT_THROW(readVoxelGroundTruth(dir / "text.bt"), InputError);
  std::ofstream(dir / "cut.bt")
      << "# Octomap OcTree binary file\nid OcTree\nsize 5\nres 0.1\ndata\n";
  EXPECT_THROW(readVoxelGroundTruth(dir / "cut.bt"), InputError);
  octomap::OcTree empty(0.1);
  empty.updateNode(octomap::point3d(0, 0, 0), false);
  ASSERT_TRUE(empty.writeBinary((dir / "free.bt").string()));
  EXPECT_THROW(readVoxelGroundTruth(dir / "free.bt"), InputError);
  VoxelOptions small;
  small.max_voxels = 10;
  EXPECT_THROW(readVoxelGroundTruth(writeWall(dir), small), InputError);
  // A valid header followed by 1 MB of 0xff bytes (every child an inner
  // node): OctoMap's own reader crashed on it (SIGSEGV); refused by the
  // walk of the node data first (common/octree_file.h).
  std::ofstream(dir / "ff.bt", std::ios::binary)
      << "# Octomap OcTree binary file\nid OcTree\nsize 5\nres 0.1\ndata\n"
      << std::string(1 << 20, '\xff');
  EXPECT_THROW(readVoxelGroundTruth(dir / "ff.bt"), InputError);
}

TEST(VoxelDistance, IsTheDistanceToTheNearestCube) {
  VoxelGroundTruth gt;
  gt.resolution_m = 0.1;
  gt.centres = {Eigen::Vector3d(0.05, 0.05, 0.05), Eigen::Vector3d(1.05, 0.05, 0.05)};
  const VoxelDistance d(gt, 1.0);
  EXPECT_DOUBLE_EQ(d.distance({0.02, 0.07, 0.01}), 0.0);                 // inside
  EXPECT_NEAR(d.distance({0.3, 0.05, 0.05}), 0.2, 1e-12);                // beside a face
  EXPECT_NEAR(d.distance({0.6, 0.05, 0.05}), 0.4, 1e-12);                // between the two
  EXPECT_NEAR(d.distance({0.2, 0.2, 0.2}), std::sqrt(3 * 0.01), 1e-12);  // off a corner
  EXPECT_NEAR(d.distance({0.05, -0.5, 0.05}), 0.5, 1e-12);               // 5 shells away
  EXPECT_NEAR(d.distance({-0.05, -0.5, 0.05}), std::hypot(0.05, 0.5), 1e-12);
  EXPECT_DOUBLE_EQ(d.distance({5.0, 5.0, 5.0}), 1.0);  // beyond: the cap
  EXPECT_DOUBLE_EQ(d.distance({NAN, 0.0, 0.0}), 1.0);
}

TEST(VoxelAccuracy, AMapOnTheWallIsAccurateAndCoversIt) {
  const VoxelGroundTruth gt = readVoxelGroundTruth(writeWall(testDir("on")));
  const VoxelAccuracy a = voxelAccuracy(gt, wallAt(1.05, 0.0, 4.0), VoxelOptions{});
  EXPECT_EQ(a.voxels, 800u);
  EXPECT_DOUBLE_EQ(a.map_to_voxels.mean_m, 0.0);  // every sample inside a voxel
  EXPECT_DOUBLE_EQ(a.coverage, 1.0);
  EXPECT_EQ(a.voxels_in_map_box, 800u);
  EXPECT_LT(a.voxels_to_map.mean_m, 1e-6);  // OctoMap stores centres as floats
}

TEST(VoxelAccuracy, AShiftedPartialMapIsScoredByTheShiftAndItsShare) {
  const VoxelGroundTruth gt = readVoxelGroundTruth(writeWall(testDir("shifted")));
  // 0.3 m in front of the wall (0.25 m from the cubes' face), half its length.
  const VoxelAccuracy a = voxelAccuracy(gt, wallAt(1.35, 0.0, 2.0), VoxelOptions{});
  EXPECT_NEAR(a.map_to_voxels.mean_m, 0.25, 1e-9);
  EXPECT_DOUBLE_EQ(a.coverage, 0.0);  // 0.3 m > one voxel edge
  // 0.05 m in front: covered where it is, half the wall.
  const VoxelAccuracy b = voxelAccuracy(gt, wallAt(1.1, 0.0, 2.0), VoxelOptions{});
  EXPECT_NEAR(b.coverage, 0.5, 0.03);
  EXPECT_NEAR(b.coverage_in_map_box, 1.0, 0.06);
}

TEST(VoxelOptions, ValidateRejectsNonsense) {
  std::string why;
  VoxelOptions o;
  EXPECT_TRUE(o.validate(&why));
  o.max_distance_m = 0;
  EXPECT_FALSE(o.validate(&why));
  o = {};
  o.mesh_sample_m = NAN;
  EXPECT_FALSE(o.validate(&why));
}

}  // namespace
}  // namespace pmap::eval
