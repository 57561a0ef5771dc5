#include "pmap/common/octree_file.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <vector>

#include "pmap/common/error.h"

namespace pmap {
namespace {

constexpr const char* kFirstLine = "# Octomap OcTree binary file";
constexpr std::size_t kMaxHeaderBytes = 65536;
// The occupancy trees OctoMap writes as .bt (the node data is the same for all).
constexpr const char* kTreeTypes[] = {"OcTree", "ColorOcTree", "OcTreeStamped"};

[[noreturn]] void fail(const std::string& file, const std::string& what) {
  throw InputError(file + ": " + what);
}

std::string trimmed(const std::string& s) {
  const std::size_t b = s.find_first_not_of(" \t\r");
  const std::size_t e = s.find_last_not_of(" \t\r");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

/// "key value" with exactly one value; false for any other shape.
bool splitKeyValue(const std::string& line, std::string& key, std::string& value) {
  const std::size_t sp = line.find_first_of(" \t");
  if (sp == std::string::npos) {
    return false;
  }
  key = line.substr(0, sp);
  value = trimmed(line.substr(sp));
  return !value.empty() && value.find_first_of(" \t") == std::string::npos;
}

std::uint64_t parseSize(const std::string& file, int line_no, const std::string& v) {
  if (v.size() > 18 || v.find_first_not_of("0123456789") != std::string::npos) {
    fail(file,
         "header line " + std::to_string(line_no) + ": size \"" + v + "\" is not a node count");
  }
  return std::strtoull(v.c_str(), nullptr, 10);
}

double parseResolution(const std::string& file, int line_no, const std::string& v) {
  char* end = nullptr;
  const double r = std::strtod(v.c_str(), &end);
  if (end != v.c_str() + v.size() || !std::isfinite(r) || r < 1e-4 || r > 1000.0) {
    fail(file, "header line " + std::to_string(line_no) + ": res \"" + v +
                   "\" is not a voxel size in [0.0001, 1000] m");
  }
  return r;
}

struct HeaderSeen {
  bool id = false;
  bool size = false;
  bool res = false;
};

/// One "id", "size" or "res" line of the header.
void readHeaderField(const std::string& file, int line_no, const std::string& line,
                     const OctreeLimits& limits, OctreeHeader& h, HeaderSeen& seen) {
  std::string key, value;
  if (!splitKeyValue(line, key, value) || (key != "id" && key != "size" && key != "res")) {
    fail(file, "header line " + std::to_string(line_no) + ": \"" + line.substr(0, 40) +
                   "\" is not \"id\", \"size\", \"res\", \"data\" or a # comment");
  }
  bool& already = key == "id" ? seen.id : key == "size" ? seen.size : seen.res;
  if (already) {
    fail(file, "header line " + std::to_string(line_no) + ": duplicate \"" + key + "\"");
  }
  already = true;
  if (key == "id") {
    h.id = value;
    bool known = false;
    for (const char* t : kTreeTypes) {
      known = known || h.id == t;
    }
    if (!known) {
      fail(file, "header: tree type \"" + value.substr(0, 40) +
                     "\" is not an occupancy tree (OcTree, ColorOcTree, OcTreeStamped)");
    }
  } else if (key == "size") {
    h.size = parseSize(file, line_no, value);
    if (h.size > limits.max_tree_nodes) {
      fail(file, "header: " + std::to_string(h.size) + " nodes, more than max_tree_nodes (" +
                     std::to_string(limits.max_tree_nodes) + ")");
    }
  } else {
    h.resolution_m = parseResolution(file, line_no, value);
  }
}

std::string at(std::size_t pos) {
  return "byte " + std::to_string(pos) + ": ";
}

/// The two bytes of child bits at `pos` (children at `child_depth`), counted
/// into `c`; returns how many children are inner nodes.
int readChildBits(const std::string& bytes, std::size_t pos, int child_depth,
                  const std::string& file, OctreeCounts& c) {
  if (bytes.size() - pos < 2) {
    fail(file, at(pos) + "truncated: the tree's data ends inside a node at depth " +
                   std::to_string(child_depth - 1));
  }
  const auto b0 = static_cast<unsigned char>(bytes[pos]);
  const auto b1 = static_cast<unsigned char>(bytes[pos + 1]);
  int inner = 0;
  for (int i = 0; i < 8; ++i) {
    // OctoMap's bit pairs: 1 = free leaf, 2 = occupied leaf, 3 = inner node.
    const unsigned code = ((i < 4 ? b0 : b1) >> (2 * (i % 4))) & 3u;
    if (code == 0) {
      continue;
    }
    ++c.nodes;
    if (code == 2) {
      ++c.occupied_leaves;
      c.occupied_voxels += std::uint64_t{1} << (3 * (kOctreeDepth - child_depth));
    } else if (code == 3) {
      if (child_depth >= kOctreeDepth) {
        fail(file, at(pos) + "an inner node below the finest level (depth " +
                       std::to_string(kOctreeDepth) + "): damaged tree");
      }
      ++inner;
    }
  }
  return inner;
}

void checkLimits(const OctreeCounts& c, const OctreeLimits& limits, std::size_t pos,
                 const std::string& file) {
  if (c.nodes > limits.max_tree_nodes) {
    fail(file, at(pos) + "more than max_tree_nodes (" + std::to_string(limits.max_tree_nodes) +
                   ") nodes");
  }
  if (c.occupied_voxels > limits.max_occupied_voxels) {
    fail(file, at(pos) + "more than max_occupied_voxels (" +
                   std::to_string(limits.max_occupied_voxels) + ") occupied voxels");
  }
}

}  // namespace

OctreeHeader parseOctreeHeader(const std::string& bytes, const std::string& file,
                               const OctreeLimits& limits) {
  const std::string first(kFirstLine);
  if (bytes.compare(0, first.size(), first) != 0) {
    fail(file, "not an OctoMap binary tree (.bt): the first line is not \"" + first +
                   "\" (OctoMap's older headerless format: convert it with convert_octree)");
  }
  OctreeHeader h;
  HeaderSeen seen;
  std::size_t pos = bytes.find('\n');
  for (int line_no = 2; pos != std::string::npos && pos + 1 <= kMaxHeaderBytes; ++line_no) {
    const std::size_t start = pos + 1;
    pos = bytes.find('\n', start);
    const std::string line =
        trimmed(bytes.substr(start, (pos == std::string::npos ? bytes.size() : pos) - start));
    if (line.empty() || line[0] == '#') {
      continue;
    }
    if (line != "data") {
      readHeaderField(file, line_no, line, limits, h, seen);
      continue;
    }
    if (!seen.id || !seen.size || !seen.res) {
      const char* missing = !seen.id ? "id" : !seen.size ? "size" : "res";
      fail(file, std::string("header: missing \"") + missing + "\" line before \"data\"");
    }
    h.data_offset = pos == std::string::npos ? bytes.size() : pos + 1;
    return h;
  }
  fail(file, "header: no \"data\" line in the first " + std::to_string(kMaxHeaderBytes) +
                 " bytes (not an OctoMap binary tree, or a damaged one)");
}

OctreeCounts checkOctreeData(const std::string& bytes, const OctreeHeader& header,
                             const std::string& file, const OctreeLimits& limits) {
  std::size_t pos = header.data_offset;
  if (header.size == 0) {
    if (pos != bytes.size()) {
      fail(file, at(pos) + "node data after a header announcing an empty tree (size 0)");
    }
    fail(file, "the tree is empty (size 0): no occupied voxel");
  }
  // Depth-first, as OctoMap reads: pending[d] = inner nodes at depth d still
  // to be read below the current node of depth d - 1 (at most 17 entries).
  OctreeCounts c;
  c.nodes = 1;                     // the root
  std::vector<int> pending = {1};  // ... to be read
  while (!pending.empty()) {
    if (pending.back() == 0) {
      pending.pop_back();
      continue;
    }
    --pending.back();
    const int child_depth = static_cast<int>(pending.size());  // the node read is one above
    const int inner = readChildBits(bytes, pos, child_depth, file, c);
    checkLimits(c, limits, pos, file);
    pos += 2;
    pending.push_back(inner);
  }
  if (pos != bytes.size()) {
    fail(file, at(pos) + std::to_string(bytes.size() - pos) +
                   " bytes after the end of the tree (damaged, or not one tree)");
  }
  if (c.nodes != header.size) {
    fail(file, "the header announces " + std::to_string(header.size) + " nodes, the data holds " +
                   std::to_string(c.nodes) + " (damaged tree)");
  }
  if (c.occupied_voxels == 0) {
    fail(file, "no occupied voxel in the tree");
  }
  return c;
}

std::string readOctreeBytes(const std::filesystem::path& file, const OctreeLimits& limits) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (ec) {
    fail(file.string(), "cannot read its size: " + ec.message());
  }
  const std::uint64_t max_bytes = 2 * limits.max_tree_nodes + kMaxHeaderBytes;
  if (size > max_bytes) {
    fail(file.string(), std::to_string(size) + " bytes, more than a tree of max_tree_nodes (" +
                            std::to_string(limits.max_tree_nodes) + ") nodes can hold");
  }
  std::ifstream in(file, std::ios::binary);
  std::string bytes(static_cast<std::size_t>(size), '\0');
  if (!in || !in.read(bytes.data(), static_cast<std::streamsize>(size)) ||
      in.peek() != std::char_traits<char>::eof()) {
    fail(file.string(), "cannot read the file (or it changed while read)");
  }
  return bytes;
}

std::string fnv1a64Hex(const std::string& bytes) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const char ch : bytes) {
    h ^= static_cast<unsigned char>(ch);
    h *= 0x100000001b3ull;
  }
  char out[17];
  std::snprintf(out, sizeof(out), "%016llx", static_cast<unsigned long long>(h));
  return out;
}

}  // namespace pmap
