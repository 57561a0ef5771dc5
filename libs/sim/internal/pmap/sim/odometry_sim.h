// Drifting wheel odometry. Each cycle the true motion increment (dx, dy, dyaw)
// in the robot frame becomes
//   dx' = (1 + scale) dx + n_xy,  dy' = (1 + scale) dy + n_xy,
//   dyaw' = dyaw + drift * |(dx, dy)| + n_yaw,
// i.e. a systematic distance scale error, a heading drift proportional to the
// distance travelled and small white noise; the odometry pose integrates the
// measured increments from (0, 0, 0). With random signs, the signs of scale and
// drift are drawn from the seed (the magnitudes are the configured ones).
#pragma once

#include <cstdint>

#include "pmap/sim/pose.h"
#include "pmap/sim/rng.h"
#include "pmap/sim/sensor_options.h"

namespace pmap::sim {

class OdometrySimulator {
 public:
  OdometrySimulator(const NoiseOptions& noise, std::uint64_t seed);

  /// Applies one cycle's true increment; returns the measured increment.
  Pose2D advance(const Pose2D& true_increment);

  /// The absolute odometry pose (as MRPT's CObservationOdometry stores it).
  const Pose2D& pose() const { return pose_; }
  double scaleError() const { return scale_; }                     ///< signed fraction
  double headingDriftRadPerM() const { return drift_rad_per_m_; }  ///< signed

 private:
  Rng rng_;
  double scale_;
  double drift_rad_per_m_;
  double sigma_xy_m_;
  double sigma_yaw_rad_;
  Pose2D pose_;
};

}  // namespace pmap::sim
