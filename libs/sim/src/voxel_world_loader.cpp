// loadVoxelWorld: the .bt file checked by our own walk (octree_file.h), then
// read by OctoMap, whose occupied leaves become the simulator's voxel set.
#include <octomap/OcTree.h>

#include <filesystem>
#include <sstream>

#include "pmap/common/error.h"
#include "pmap/common/octree_file.h"
#include "pmap/common/quiet_cerr.h"
#include "pmap/sim/voxel_world.h"

namespace pmap::sim {
namespace {

namespace fs = std::filesystem;

/// The whole file, after checking that it exists and is not larger than a
/// tree within the limits can be (two bytes per inner node plus the header).
std::string readTreeBytes(const OctomapSpec& spec) {
  const std::string file = spec.file.string();
  std::error_code ec;
  if (!fs::exists(spec.file, ec)) {
    throw InputError(file + ": OctoMap tree not found (" + spec.where + ".file in the world file)");
  }
  if (!fs::is_regular_file(spec.file, ec)) {
    throw InputError(file + ": not a regular file (" + spec.where + ".file)");
  }
  return readOctreeBytes(spec.file, {spec.max_tree_nodes, spec.max_occupied_voxels});
}

}  // namespace

VoxelWorld loadVoxelWorld(const OctomapSpec& spec) {
  const std::string file = spec.file.string();
  const std::string bytes = readTreeBytes(spec);
  const OctreeLimits limits{spec.max_tree_nodes, spec.max_occupied_voxels};
  const OctreeHeader header = parseOctreeHeader(bytes, file, limits);
  const OctreeCounts counts = checkOctreeData(bytes, header, file, limits);

  octomap::OcTree tree(header.resolution_m);
  bool read = false;
  {
    std::istringstream in(bytes);  // a fresh stream at the file's first byte
    const QuietCerr quiet;
    read = tree.readBinary(in);
  }
  if (!read) {
    throw InputError(file + ": OctoMap's reader refused the tree (OcTree::readBinary failed)");
  }
  std::vector<VoxelWorld::Block> blocks;
  blocks.reserve(static_cast<std::size_t>(counts.occupied_leaves));
  std::uint64_t voxels = 0;
  for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
    if (!tree.isNodeOccupied(*it)) {
      continue;
    }
    const int side = 1 << (kOctreeDepth - static_cast<int>(it.getDepth()));
    const octomap::OcTreeKey key = it.getKey();
    VoxelWorld::Block b;
    b.side = side;
    for (int a = 0; a < 3; ++a) {  // a leaf's key lies inside it: its lowest voxel
      b.corner[a] = static_cast<int>(key[a] & ~(side - 1)) - 32768;
    }
    blocks.push_back(b);
    voxels += static_cast<std::uint64_t>(side) * side * side;
  }
  if (voxels != counts.occupied_voxels) {
    throw InputError(file + ": OctoMap read " + std::to_string(voxels) +
                     " occupied voxels where the file's data holds " +
                     std::to_string(counts.occupied_voxels) + " (damaged tree)");
  }
  OctreeFileInfo info;
  info.file = file;
  info.file_as_written = spec.file_as_written;
  info.bytes = bytes.size();
  info.fnv1a_64 = fnv1a64Hex(bytes);
  info.tree_type = header.id;
  info.tree_nodes = counts.nodes;
  info.occupied_leaves = counts.occupied_leaves;
  return VoxelWorld(tree.getResolution(), blocks, std::move(info));
}

}  // namespace pmap::sim
