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

SimulatedScan simulateScan(const BeamCaster& cast, const Pose2D& robot, const LaserOptions& laser,
                           double sigma_m, Rng& rng) {
  const RigidTransform sensor = laserToWorld(robot, laser);
  const Eigen::Vector3d origin = sensor.translation;
  const std::size_t n = static_cast<std::size_t>(laser.beams);
  SimulatedScan scan;
  scan.ranges_m.resize(n);
  scan.valid.resize(n);
  scan.hit_ids.resize(n);
  scan.true_ranges_m.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = beamAngle(laser, static_cast<int>(i));
    const Eigen::Vector3d dir = sensor.rotation * Eigen::Vector3d(std::cos(a), std::sin(a), 0.0);
    const std::optional<BeamHit> hit = cast(origin, dir, laser.max_range_m);
    const double noise = sigma_m * rng.normal();
    scan.hit_ids[i] = hit ? hit->id : -1;
    scan.true_ranges_m[i] = hit ? hit->t_m : laser.max_range_m;
    const double noisy = hit ? hit->t_m + noise : laser.max_range_m;
    const bool ok = hit && noisy > 0.0 && noisy <= laser.max_range_m;
    scan.valid[i] = ok ? 1 : 0;
    scan.ranges_m[i] = static_cast<float>(ok ? noisy : laser.max_range_m);
  }
  return scan;
}

SimulatedScan simulateScan(const RayCaster& caster, const Pose2D& robot, const LaserOptions& laser,
                           double sigma_m, Rng& rng) {
  const RigidTransform sensor = laserToWorld(robot, laser);
  // Every beam lies in the sensor's x-y plane: only objects meeting it matter.
  const std::vector<int> candidates =
      caster.selectNearPlane(sensor.translation, sensor.rotation.col(2), laser.max_range_m);
  const BeamCaster cast = [&](const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                              double max_range_m) -> std::optional<BeamHit> {
    const auto hit = caster.cast(origin, dir, max_range_m, &candidates);
    return hit ? std::optional<BeamHit>(BeamHit{hit->t, hit->id}) : std::nullopt;
  };
  return simulateScan(cast, robot, laser, sigma_m, rng);
}

}  // namespace pmap::sim
