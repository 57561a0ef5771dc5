// The OctoMap baseline (liboctomap directly, not MRPT's wrapper): every
// structure scan of a map directory inserted from its sensor origin
// (scans.csv) with its points (points.ply), at a given resolution.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

#include "pmap/eval/map_files.h"

namespace octomap {
class OcTree;
}

namespace pmap::eval {

/// Sensor origins of the structure scans, by scan index (scans.csv's `scan`
/// and `x,y,z`, as points.ply's `scan`).
using ScanOrigins = std::unordered_map<std::int64_t, Eigen::Vector3d>;

/// Reads DIR/scans.csv strictly (header must start with
/// `scan,timestamp,label,x,y,z`). Throws InputError naming file and line.
ScanOrigins readScanOrigins(const std::filesystem::path& csv);

struct OctomapOptions {
  double resolution_m = 0.05;  ///< leaf size (m)
  double max_range_m = -1.0;   ///< OctoMap's maxrange: < 0 inserts every ray whole
  bool validate(std::string* why) const;
};

struct OctomapResult {
  double resolution_m = 0;
  std::size_t scans = 0;            ///< scans inserted
  std::size_t points = 0;           ///< end points inserted
  double insert_s = 0;              ///< wall time of the insertions alone
  std::size_t memory_bytes = 0;     ///< OcTree::memoryUsage() after insertion
  std::size_t file_bytes = 0;       ///< size of the .bt file (OcTree::writeBinary)
  std::string bt_file;              ///< the .bt file's bytes (octovis opens it)
  std::size_t nodes = 0;            ///< OcTree::size()
  std::size_t leaves = 0;           ///< OcTree::getNumLeafNodes()
  std::size_t occupied_leaves = 0;  ///< leaves with occupancy above the threshold
  /// Centres of the occupied voxels at the finest resolution (pruned
  /// occupied leaves expanded), in the map frame.
  std::vector<Eigen::Vector3d> occupied_centres;
};

/// The bytes of the tree's .bt file, as OcTree::writeBinary writes them
/// (it turns the tree to maximum likelihood and prunes it first, as that
/// does), without liboctomap's debug output.
std::string btFileContent(octomap::OcTree& tree);

/// The .bt file name map-eval writes for a resolution: "octomap_5cm.bt" for
/// 0.05, "octomap_10cm.bt" for 0.10 ("octomap_2.5cm.bt" for 0.025):
/// products::OutputLayout::octomapFile.
std::string octomapFileName(double resolution_m);

/// Builds the tree: per scan (in scans.csv order of the points' first
/// appearance), insertPointCloud(points, origin). Points whose scan has no
/// origin are an InputError naming `points_ply`. Throws std::invalid_argument
/// for invalid options.
OctomapResult buildOctomap(const ScanOrigins& origins, const MapPoints& points,
                           const OctomapOptions& options,
                           const std::filesystem::path& points_ply = "points.ply");

}  // namespace pmap::eval
