// Checks an OctoMap binary tree file (.bt, OcTree::writeBinary) before
// OctoMap reads it. OctoMap's reader is lenient: it recurses as deep as the
// data says (a crafted or truncated file overflows the stack: it reads
// uninitialised child bits past the end), allocates a node per child bit
// before it notices a size mismatch, and reports on std::cerr. This walk reads
// the same header and the same depth-first child bits (two bytes per inner
// node, two bits per child: 00 unknown, 01 occupied leaf, 10 free leaf, 11
// inner node) without allocating anything per node, so that a damaged or huge
// file is refused with one line before any memory is spent on it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace pmap {

/// The header lines of a .bt file.
struct OctreeHeader {
  std::string id;               ///< tree type, e.g. "OcTree"
  std::uint64_t size = 0;       ///< the number of nodes the header announces
  double resolution_m = 0.0;    ///< voxel edge at the finest level
  std::size_t data_offset = 0;  ///< first byte of the node data
};

/// What the walk found in the node data.
struct OctreeCounts {
  std::uint64_t nodes = 0;            ///< every node, the root included
  std::uint64_t occupied_leaves = 0;  ///< leaves marked occupied, at any depth
  std::uint64_t occupied_voxels = 0;  ///< the same, in voxels of the finest level
};

struct OctreeLimits {
  std::uint64_t max_tree_nodes = 20000000;
  std::uint64_t max_occupied_voxels = 20000000;
};

/// OctoMap's trees are 16 levels deep: keys are 16-bit per axis.
constexpr int kOctreeDepth = 16;

/// Parses the header of `bytes` (the whole file). Throws InputError naming
/// `file` for a missing or wrong first line, an unknown keyword or tree type,
/// a resolution that is not a positive number, a missing "data" line, or a
/// node count above limits.max_tree_nodes.
OctreeHeader parseOctreeHeader(const std::string& bytes, const std::string& file,
                               const OctreeLimits& limits);

/// Walks the node data after the header. Throws InputError naming `file`
/// (and the byte offset) for truncated data, an inner node below the finest
/// level, bytes after the tree, a node count different from the header's,
/// more than max_tree_nodes nodes or max_occupied_voxels occupied voxels, and
/// a tree without any occupied voxel.
OctreeCounts checkOctreeData(const std::string& bytes, const OctreeHeader& header,
                             const std::string& file, const OctreeLimits& limits);

/// The bytes of the .bt file `file`, refused (InputError naming it) when it
/// is larger than a tree of limits.max_tree_nodes nodes can be (2 bytes per
/// node and a 64 KiB header) or cannot be read whole.
std::string readOctreeBytes(const std::filesystem::path& file, const OctreeLimits& limits);

/// FNV-1a (64 bit) of `bytes` as 16 hex digits: identifies the tree a run used.
std::string fnv1a64Hex(const std::string& bytes);

}  // namespace pmap
