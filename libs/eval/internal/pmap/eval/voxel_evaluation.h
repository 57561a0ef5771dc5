// map-eval --gt-octomap: a map scored against the occupied voxels of an
// OctoMap (.bt) as ground truth (doc/evaluation.md, "Voxel ground truth"):
// so that any building someone has a 3D voxel map of can serve as a test.
// The map must be in the tree's frame (with --gt too, the map is first
// moved by the pose alignment, as every other figure).
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pmap/eval/map_accuracy.h"
#include "pmap/eval/triangle_index.h"

namespace pmap::eval {

/// The occupied voxels at the tree's finest resolution (pruned leaves
/// expanded): their centres.
struct VoxelGroundTruth {
  double resolution_m = 0;
  std::vector<Eigen::Vector3d> centres;
};

struct VoxelOptions {
  double mesh_sample_m = 0.05;        ///< map triangles sampled at about this spacing (m)
  double max_distance_m = 1.0;        ///< distances beyond count as this (m)
  std::size_t max_voxels = 20000000;  ///< a tree with more occupied voxels is refused
  bool validate(std::string* why) const;
};

/// Reads an OcTree binary file (.bt, OcTree::writeBinary). Throws InputError
/// naming the file when it is missing, not an OcTree binary file, damaged,
/// has no occupied voxel or more than options.max_voxels.
VoxelGroundTruth readVoxelGroundTruth(const std::filesystem::path& bt,
                                      const VoxelOptions& options = {});

/// Distance from p to the nearest occupied voxel cube (0 inside one), at most
/// max_distance_m: an exact search over the voxels in growing shells.
class VoxelDistance {
 public:
  VoxelDistance(const VoxelGroundTruth& gt, double max_distance_m);
  double distance(const Eigen::Vector3d& p) const;

 private:
  std::int64_t key(std::int64_t x, std::int64_t y, std::int64_t z) const;
  double res_;
  double max_;
  std::vector<std::int64_t> keys_;  ///< sorted
};

struct VoxelAccuracy {
  std::size_t voxels = 0;
  ErrorStats map_to_voxels;  ///< map samples (area-weighted) to the nearest occupied cube
  ErrorStats voxels_to_map;  ///< occupied voxel centres to the map (capped)
  double coverage = 0;       ///< occupied voxels whose centre is within one voxel edge of the map
  std::size_t voxels_in_map_box = 0;  ///< occupied voxels inside the map's bounding box (+1 edge)
  double coverage_in_map_box = 0;     ///< ... and the share of those covered
};

/// `map_triangles` in the tree's frame.
VoxelAccuracy voxelAccuracy(const VoxelGroundTruth& gt, const std::vector<Triangle3>& map_triangles,
                            const VoxelOptions& options);

/// eval.json's `voxel_gt`.
nlohmann::json voxelJson(const VoxelAccuracy& a, const VoxelGroundTruth& gt,
                         const std::filesystem::path& bt, const VoxelOptions& options);

}  // namespace pmap::eval
