// A voxel world: the occupied voxels of an OctoMap tree, at the tree's finest
// resolution, as the simulator's own compact set (bricks of 4 x 4 x 4 voxels,
// one 64-bit mask each, sorted by brick). Voxel (i, j, k) is the cube
// [i, i + 1) x [j, j + 1) x [k, k + 1) times the resolution in the tree's
// frame, which is the simulated world frame (OctoMap's key of that voxel is
// (i, j, k) + 32768). Free and unknown space are not stored: both are free
// for the lasers (doc/simulator.md, "Voxel worlds").
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "pmap/sim/world_spec.h"

namespace pmap::sim {

/// What the simulator read from the .bt file (for gt.json and the summary).
struct OctreeFileInfo {
  std::string file;              ///< the path read
  std::string file_as_written;   ///< as the world file gives it
  std::uint64_t bytes = 0;       ///< file size
  std::string fnv1a_64;          ///< FNV-1a 64-bit hash of the file, 16 hex digits
  std::string tree_type;         ///< the header's id, e.g. "OcTree"
  std::uint64_t tree_nodes = 0;  ///< nodes of the tree, the root included
  std::uint64_t occupied_leaves = 0;
};

class VoxelWorld {
 public:
  /// An occupied cube of `side` x `side` x `side` voxels (side a power of two,
  /// 1 to 2^16) whose lowest voxel is `corner` (OctoMap's pruned leaves).
  struct Block {
    Eigen::Vector3i corner = Eigen::Vector3i::Zero();
    int side = 1;
  };

  /// Voxel indices are limited to OctoMap's key range [-32768, 32768) per axis.
  static constexpr int kMinIndex = -32768;
  static constexpr int kMaxIndex = 32767;

  /// Throws std::invalid_argument for a resolution that is not positive, a
  /// block outside the key range or a side that is not a power of two. An
  /// empty world (no block) is valid: every ray misses.
  VoxelWorld(double resolution_m, const std::vector<Block>& blocks, OctreeFileInfo info = {});

  double resolution_m() const { return resolution_m_; }
  std::uint64_t occupiedVoxels() const { return occupied_voxels_; }
  bool empty() const { return brick_keys_.empty(); }
  /// Inclusive index bounds of the occupied voxels (meaningless when empty()).
  const Eigen::Vector3i& minIndex() const { return min_index_; }
  const Eigen::Vector3i& maxIndex() const { return max_index_; }
  const OctreeFileInfo& info() const { return info_; }

  /// The voxel containing p (floor(p / resolution)); p must be finite and
  /// within the key range (check inKeyRange first when it may not be).
  Eigen::Vector3i voxelOf(const Eigen::Vector3d& p) const;
  bool inKeyRange(const Eigen::Vector3d& p) const;
  Eigen::Vector3d voxelCentre(const Eigen::Vector3i& v) const;
  /// False outside the key range.
  bool occupied(const Eigen::Vector3i& v) const;

  /// The brick holding voxel v (in the key range) and v's bit in its mask.
  static std::uint64_t brickKey(const Eigen::Vector3i& v);
  static int brickBit(const Eigen::Vector3i& v);
  /// The occupancy mask of a brick, 0 if it holds no occupied voxel.
  std::uint64_t brickMask(std::uint64_t brick_key) const;

 private:
  double resolution_m_;
  std::vector<std::uint64_t> brick_keys_;   ///< sorted, unique
  std::vector<std::uint64_t> brick_masks_;  ///< parallel to brick_keys_
  std::uint64_t occupied_voxels_ = 0;
  Eigen::Vector3i min_index_ = Eigen::Vector3i::Zero();
  Eigen::Vector3i max_index_ = Eigen::Vector3i::Zero();
  OctreeFileInfo info_;
};

/// Reads the tree of `spec` (octree_file.h checks it first, then OctoMap's
/// reader builds it; its messages on std::cerr are silenced) and keeps its
/// occupied voxels. Throws InputError naming the file: missing, unreadable,
/// larger than the limits allow, not an OctoMap binary tree, damaged, or
/// without any occupied voxel.
VoxelWorld loadVoxelWorld(const OctomapSpec& spec);

}  // namespace pmap::sim
