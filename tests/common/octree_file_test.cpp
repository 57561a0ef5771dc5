#include "pmap/common/octree_file.h"

#include <gtest/gtest.h>

#include <string>

#include "pmap/common/error.h"

namespace pmap {
namespace {

const std::string kFirst = "# Octomap OcTree binary file\n";

std::string header(const std::string& size, const std::string& res = "0.1",
                   const std::string& id = "OcTree") {
  return kFirst + "# a comment\nid " + id + "\nsize " + size + "\nres " + res + "\ndata\n";
}

/// One occupied voxel: a chain of inner nodes (child 0) from the root down to
/// depth 15, whose child 0 is an occupied leaf at the finest level. 17 nodes.
std::string chainData(unsigned last_code = 2) {
  std::string d;
  for (int depth = 0; depth < 15; ++depth) {
    d += '\x03';  // child 0: inner node
    d += '\x00';
  }
  d += static_cast<char>(last_code);  // child 0 of the depth-15 node
  d += '\x00';
  return d;
}

std::string errorOf(const std::string& bytes, const OctreeLimits& limits = {}) {
  try {
    const OctreeHeader h = parseOctreeHeader(bytes, "t.bt", limits);
    checkOctreeData(bytes, h, "t.bt", limits);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(OctreeFile, ReadsHeaderAndCountsTheChain) {
  const std::string bytes = header("17") + chainData();
  const OctreeHeader h = parseOctreeHeader(bytes, "t.bt", {});
  EXPECT_EQ(h.id, "OcTree");
  EXPECT_EQ(h.size, 17u);
  EXPECT_DOUBLE_EQ(h.resolution_m, 0.1);
  EXPECT_EQ(h.data_offset, header("17").size());
  const OctreeCounts c = checkOctreeData(bytes, h, "t.bt", {});
  EXPECT_EQ(c.nodes, 17u);
  EXPECT_EQ(c.occupied_leaves, 1u);
  EXPECT_EQ(c.occupied_voxels, 1u);
}

TEST(OctreeFile, CountsCoarseLeavesAsTheirVoxels) {
  // Root with child 0 inner, whose child 3 is an occupied leaf at depth 2 (8^14 voxels).
  const std::string bytes = header("3") + std::string("\x03\x00\x80\x00", 4);
  OctreeLimits limits;
  EXPECT_NE(errorOf(bytes, limits).find("more than max_occupied_voxels (20000000)"),
            std::string::npos);
  limits.max_occupied_voxels = std::uint64_t{1} << 42;
  const OctreeHeader h = parseOctreeHeader(bytes, "t.bt", limits);
  EXPECT_EQ(checkOctreeData(bytes, h, "t.bt", limits).occupied_voxels, std::uint64_t{1} << 42);
}

TEST(OctreeFile, RefusesBadHeaders) {
  const std::string data = chainData();
  EXPECT_NE(errorOf("").find("not an OctoMap binary tree"), std::string::npos);
  EXPECT_NE(errorOf("hello\n" + data).find("not an OctoMap binary tree"), std::string::npos);
  EXPECT_NE(errorOf(header("17", "abc") + data).find("res \"abc\""), std::string::npos);
  EXPECT_NE(errorOf(header("17", "0") + data).find("res \"0\""), std::string::npos);
  EXPECT_NE(errorOf(header("17", "nan") + data).find("res"), std::string::npos);
  EXPECT_NE(errorOf(header("-3") + data).find("size \"-3\""), std::string::npos);
  EXPECT_NE(errorOf(header("17", "0.1", "CountingOcTree") + data).find("not an occupancy tree"),
            std::string::npos);
  EXPECT_NE(errorOf(kFirst + "id OcTree\nres 0.1\ndata\n" + data).find("missing \"size\""),
            std::string::npos);
  EXPECT_NE(errorOf(kFirst + "id OcTree\nsize 17\nres 0.1\n").find("no \"data\" line"),
            std::string::npos);
  EXPECT_NE(errorOf(kFirst + "id OcTree\nid OcTree\n").find("duplicate \"id\""), std::string::npos);
  EXPECT_NE(errorOf(kFirst + "colour red\n").find("header line 2"), std::string::npos);
  OctreeLimits small;
  small.max_tree_nodes = 10;
  EXPECT_NE(errorOf(header("17") + data, small).find("more than max_tree_nodes (10)"),
            std::string::npos);
}

TEST(OctreeFile, RefusesDamagedData) {
  const std::string data = chainData();
  const std::string truncated = errorOf(header("17") + data.substr(0, data.size() - 1));
  EXPECT_NE(truncated.find("truncated"), std::string::npos) << truncated;
  EXPECT_NE(truncated.find("t.bt: byte "), std::string::npos) << truncated;
  EXPECT_NE(errorOf(header("17") + data + "x").find("1 bytes after the end of the tree"),
            std::string::npos);
  EXPECT_NE(errorOf(header("18") + data).find("announces 18 nodes, the data holds 17"),
            std::string::npos);
  EXPECT_NE(errorOf(header("17") + chainData(3)).find("below the finest level"), std::string::npos);
  EXPECT_NE(errorOf(header("17") + chainData(1)).find("no occupied voxel"), std::string::npos);
}

// All-ones data makes OctoMap's reader recurse without bound (a stack
// overflow); the walk stops at the finest level or at the node limit.
TEST(OctreeFile, AllOnesDataIsRefusedWithoutRecursion) {
  const std::string ones(1 << 20, '\xff');
  EXPECT_NE(errorOf(header("20000000") + ones).find("below the finest level"), std::string::npos);
  OctreeLimits small;
  small.max_tree_nodes = 50;
  EXPECT_NE(errorOf(header("50") + ones, small).find("more than max_tree_nodes"),
            std::string::npos);
}

TEST(OctreeFile, EmptyTrees) {
  EXPECT_NE(errorOf(header("0")).find("the tree is empty"), std::string::npos);
  EXPECT_NE(errorOf(header("0") + "ab").find("empty tree (size 0)"), std::string::npos);
  EXPECT_NE(errorOf(header("1") + std::string(2, '\0')).find("no occupied voxel"),
            std::string::npos);
}

TEST(OctreeFile, AcceptsCommentsAndBlankLines) {
  const std::string bytes =
      kFirst + "\n# made by hand\n  \nid OcTree\nsize 17\nres 0.05\ndata\n" + chainData();
  const OctreeHeader h = parseOctreeHeader(bytes, "t.bt", {});
  EXPECT_DOUBLE_EQ(h.resolution_m, 0.05);
  EXPECT_EQ(checkOctreeData(bytes, h, "t.bt", {}).nodes, 17u);
}

TEST(OctreeFile, Fnv1a64) {
  EXPECT_EQ(fnv1a64Hex(""), "cbf29ce484222325");
  EXPECT_EQ(fnv1a64Hex("a"), "af63dc4c8601ec8c");
}

}  // namespace
}  // namespace pmap
