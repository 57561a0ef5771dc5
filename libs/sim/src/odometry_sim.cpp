#include "pmap/sim/odometry_sim.h"

#include <cmath>

namespace pmap::sim {

OdometrySimulator::OdometrySimulator(const NoiseOptions& noise, std::uint64_t seed)
    : rng_(deriveSeed(seed, "odometry")),
      scale_(noise.odometry_scale_error),
      drift_rad_per_m_(degToRad(noise.odometry_heading_drift_deg_per_m)),
      sigma_xy_m_(noise.odometry_sigma_xy_m),
      sigma_yaw_rad_(degToRad(noise.odometry_sigma_yaw_deg)) {
  if (noise.odometry_random_signs) {
    Rng signs(deriveSeed(seed, "odometry-signs"));
    scale_ = signs.coin() ? scale_ : -scale_;
    drift_rad_per_m_ = signs.coin() ? drift_rad_per_m_ : -drift_rad_per_m_;
  }
}

Pose2D OdometrySimulator::advance(const Pose2D& inc) {
  const double dist = std::hypot(inc.x, inc.y);
  Pose2D measured;
  measured.x = (1.0 + scale_) * inc.x + sigma_xy_m_ * rng_.normal();
  measured.y = (1.0 + scale_) * inc.y + sigma_xy_m_ * rng_.normal();
  measured.yaw = wrapAngle(inc.yaw + drift_rad_per_m_ * dist + sigma_yaw_rad_ * rng_.normal());
  pose_ = compose(pose_, measured);
  return measured;
}

}  // namespace pmap::sim
