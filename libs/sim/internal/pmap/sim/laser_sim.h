// Simulated 2D laser scans. Beam geometry follows MRPT's
// CObservation2DRangeScan with rightToLeft = true: beam i has angle
// a_i = -aperture/2 + i * aperture / (N - 1) and direction (cos a_i, sin a_i, 0)
// in the sensor frame; the sensor frame is the mount pose (CPose3D convention)
// composed on the robot pose. All of it is computed here with our own
// rotations (pose.h), and checked against MRPT in the tests.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <vector>

#include "pmap/sim/pose.h"
#include "pmap/sim/ray_caster.h"
#include "pmap/sim/rng.h"
#include "pmap/sim/sensor_options.h"

namespace pmap::sim {

/// One simulated scan: what goes into the rawlog and the true hit per beam.
struct SimulatedScan {
  std::vector<float> ranges_m;        ///< noisy; max_range_m where invalid
  std::vector<char> valid;            ///< 1 if a hit within max range (after noise)
  std::vector<int> hit_ids;           ///< id hit by the true ray, -1 if none within max range
  std::vector<double> true_ranges_m;  ///< noise-free distance, max_range_m if no hit
};

/// Angle of beam i in the sensor frame, radians.
double beamAngle(const LaserOptions& laser, int beam);
/// The mount pose of a laser on the robot (radians).
Pose6D laserMountPose(const LaserOptions& laser);
/// The sensor frame in the world for a planar robot pose.
RigidTransform laserToWorld(const Pose2D& robot, const LaserOptions& laser);
/// Unit direction of beam i in the world frame.
Eigen::Vector3d beamDirectionInWorld(const Pose2D& robot, const LaserOptions& laser, int beam);

/// The true hit of one beam: distance along its unit direction and the id of
/// what it hit (-1 where objects have no ids, as voxels).
struct BeamHit {
  double t_m = 0.0;
  int id = -1;
  /// The surface's unit normal at the hit; zero where unknown (voxels): no
  /// incidence effects there.
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  /// The beam went through glass on its way (noise.laser.glass_*).
  bool through_glass = false;
};
/// Casts one beam from `origin` along the unit `dir`; nullopt without a hit
/// within `max_range_m`.
using BeamCaster = std::function<std::optional<BeamHit>(
    const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double max_range_m)>;

/// Casts every beam from the sensor origin and draws its range error from
/// `rng`: N(0, sigma^2) with sigma = noise.range_sigma_m, one draw per beam,
/// hit or not; with noise.laser's effects on, sigma follows the range and
/// the incidence, and returns are lost, spurious or mixed at depth edges
/// (extra draws only for the effects that are on). A noisy range beyond max
/// range (or not positive) becomes invalid with range = max range. A
/// spurious or mixed return lies on no object: its hit id is -1.
SimulatedScan simulateScan(const BeamCaster& cast, const Pose2D& robot, const LaserOptions& laser,
                           const NoiseOptions& noise, Rng& rng);
/// The same against a World's surfaces and clutter (only the objects whose
/// bounding sphere meets the scan plane are tried) and its people where
/// they are `t_s` seconds after the run's start. A beam goes through glass
/// unless it meets the pane within noise.laser.glass_return_deg of its
/// normal.
SimulatedScan simulateScan(const RayCaster& caster, const Pose2D& robot, const LaserOptions& laser,
                           const NoiseOptions& noise, Rng& rng, double t_s = 0.0);
}  // namespace pmap::sim
