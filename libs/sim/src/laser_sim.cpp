#include "pmap/sim/laser_sim.h"

#include <cmath>

namespace pmap::sim {

double beamAngle(const LaserOptions& laser, int beam) {
  const double aperture = degToRad(laser.aperture_deg);
  return -0.5 * aperture + beam * aperture / (laser.beams - 1);
}

Pose6D laserMountPose(const LaserOptions& laser) {
  return pose6DFromDegrees({laser.position_m[0], laser.position_m[1], laser.position_m[2],
                            laser.ypr_deg[0], laser.ypr_deg[1], laser.ypr_deg[2]});
}

RigidTransform laserToWorld(const Pose2D& robot, const LaserOptions& laser) {
  return compose(toTransform(robot), toTransform(laserMountPose(laser)));
}

Eigen::Vector3d beamDirectionInWorld(const Pose2D& robot, const LaserOptions& laser, int beam) {
  const double a = beamAngle(laser, beam);
  const Eigen::Vector3d in_sensor(std::cos(a), std::sin(a), 0.0);
  const Eigen::Vector3d d = laserToWorld(robot, laser).rotation * in_sensor;
  return d;
}

SimulatedScan simulateScan(const RayCaster& caster, const Pose2D& robot, const LaserOptions& laser,
                           double sigma_m, Rng& rng) {
  const RigidTransform sensor = laserToWorld(robot, laser);
  const Eigen::Vector3d origin = sensor.translation;
  // Every beam lies in the sensor's x-y plane: only objects meeting it matter.
  const Eigen::Vector3d plane_normal = sensor.rotation.col(2);
  const std::vector<int> candidates =
      caster.selectNearPlane(origin, plane_normal, laser.max_range_m);
  const std::size_t n = static_cast<std::size_t>(laser.beams);
  SimulatedScan scan;
  scan.ranges_m.resize(n);
  scan.valid.resize(n);
  scan.hit_ids.resize(n);
  scan.true_ranges_m.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = beamAngle(laser, static_cast<int>(i));
    const Eigen::Vector3d dir = sensor.rotation * Eigen::Vector3d(std::cos(a), std::sin(a), 0.0);
    const auto hit = caster.cast(origin, dir, laser.max_range_m, &candidates);
    const double noise = sigma_m * rng.normal();
    scan.hit_ids[i] = hit ? hit->id : -1;
    scan.true_ranges_m[i] = hit ? hit->t : laser.max_range_m;
    const double noisy = hit ? hit->t + noise : laser.max_range_m;
    const bool ok = hit && noisy > 0.0 && noisy <= laser.max_range_m;
    scan.valid[i] = ok ? 1 : 0;
    scan.ranges_m[i] = static_cast<float>(ok ? noisy : laser.max_range_m);
  }
  return scan;
}

}  // namespace pmap::sim
