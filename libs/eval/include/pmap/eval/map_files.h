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

/// Throws InputError naming `path` unless it is a regular file (or a link to
/// one): "PATH: is a directory, not a file", "PATH: not found".
void requireRegularFile(const std::filesystem::path& path);

/// Reads DIR/points.ply (x y z scan beam surface). x, y, z must be finite;
/// scan, beam and surface finite integers in int range. Throws InputError
/// naming the file and the vertex.
MapPoints readMapPoints(const std::filesystem::path& ply);

/// Reads DIR/poses.txt. Throws InputError.
poses::Trajectory readMapPoses(const std::filesystem::path& poses_txt);

}  // namespace pmap::eval
