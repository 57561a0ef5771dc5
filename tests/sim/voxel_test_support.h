// Helpers of the voxel-world tests: small OctoMap trees written with OctoMap
// itself (a closed box room, a solid block that OctoMap prunes into coarser
// leaves) and world files naming them.
#pragma once

#include <octomap/OcTree.h>

#include <Eigen/Core>
#include <filesystem>
#include <string>

namespace pmap::sim::test {

/// A closed box room: its free inside is voxels [lo, hi) (indices), its walls,
/// floor and ceiling the one-voxel shell around it; optionally a solid block of
/// `block_side` voxels with lowest voxel `block_corner` (pruned by OctoMap when
/// aligned). Returns the number of occupied voxels.
inline std::size_t writeBoxRoomTree(const std::filesystem::path& path, double res,
                                    const Eigen::Vector3i& lo, const Eigen::Vector3i& hi,
                                    const Eigen::Vector3i& block_corner = Eigen::Vector3i::Zero(),
                                    int block_side = 0) {
  octomap::OcTree tree(res);
  auto key = [](int i, int j, int k) {
    return octomap::OcTreeKey(static_cast<octomap::key_type>(i + 32768),
                              static_cast<octomap::key_type>(j + 32768),
                              static_cast<octomap::key_type>(k + 32768));
  };
  std::size_t count = 0;
  for (int i = lo.x() - 1; i <= hi.x(); ++i) {
    for (int j = lo.y() - 1; j <= hi.y(); ++j) {
      for (int k = lo.z() - 1; k <= hi.z(); ++k) {
        const bool shell =
            i < lo.x() || i >= hi.x() || j < lo.y() || j >= hi.y() || k < lo.z() || k >= hi.z();
        const Eigen::Vector3i v(i, j, k);
        const bool in_block = block_side > 0 && (v.array() >= block_corner.array()).all() &&
                              (v.array() < block_corner.array() + block_side).all();
        if (shell || in_block) {
          tree.updateNode(key(i, j, k), true);
          ++count;
        } else {
          tree.updateNode(key(i, j, k), false);  // the room's inside is known free
        }
      }
    }
  }
  tree.writeBinary(path.string());
  return count;
}

/// A world file (JSON text) for the tree at `bt`.
inline std::string voxelWorldJson(const std::string& bt, const std::string& waypoints,
                                  const std::string& extra = "") {
  return R"({"name": "box", "octomap": {"file": ")" + bt + R"("},
  "path": {"waypoints": )" +
         waypoints + R"(}, "noise": {"range_sigma_m": 0.0})" + extra + "}";
}

}  // namespace pmap::sim::test
