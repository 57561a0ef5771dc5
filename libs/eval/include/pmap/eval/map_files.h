// What map-eval reads from a planar-mapper output directory: the files, not
// the mapper's internals.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <vector>

#include "pmap/poses/trajectory.h"

namespace pmap::eval {

struct MapPoints {
  std::vector<Eigen::Vector3d> xyz;
  std::vector<int> scan;
  std::vector<int> beam;
  std::vector<int> surface;
};

/// Reads DIR/points.ply (x y z scan beam surface). Throws InputError.
MapPoints readMapPoints(const std::filesystem::path& ply);

/// Reads DIR/poses.txt. Throws InputError.
poses::Trajectory readMapPoses(const std::filesystem::path& poses_txt);

}  // namespace pmap::eval
