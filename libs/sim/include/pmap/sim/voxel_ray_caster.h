// The simulator's own ray casting into a voxel world: a 3D digital
// differential analyser (Amanatides & Woo, "A Fast Voxel Traversal Algorithm
// for Ray Tracing", Eurographics 1987) over the finest voxels, clipped to the
// box of the occupied voxels. The range reported is the exact distance at
// which the ray enters the first occupied voxel cube (its face), which is
// what a laser measures on the voxel model and what map-eval's distance to
// the occupied cubes scores against.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "pmap/sim/voxel_world.h"

namespace pmap::sim {

struct VoxelHit {
  double t = 0.0;                                   ///< distance along the unit direction
  Eigen::Vector3i voxel = Eigen::Vector3i::Zero();  ///< the occupied voxel entered
};

class VoxelRayCaster {
 public:
  /// Keeps a reference: `world` must outlive the caster.
  explicit VoxelRayCaster(const VoxelWorld& world) : world_(world) {}

  /// The first occupied voxel along origin + t * dir (`dir` of unit length)
  /// with t in [0, t_max]; t = 0 if the origin lies in an occupied voxel.
  /// Unknown and free space let the ray through.
  std::optional<VoxelHit> cast(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                               double t_max) const;

  const VoxelWorld& world() const { return world_; }

 private:
  const VoxelWorld& world_;
};

}  // namespace pmap::sim
