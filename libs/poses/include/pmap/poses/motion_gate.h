// Drops physically implausible motion before it reaches the poses: one
// flipped bit in one odometry reading (x from 6.1 m to 2.6e10 m) otherwise
// moves the robot, and every point placed after it, to astronomical
// coordinates (doc/poses.md, "Implausible motion").
//
// A step from the last accepted pose is implausible when its translation
// exceeds max_step_m + max_speed_mps * dt, or its rotation exceeds
// max_step_deg + max_turn_rate_dps * dt (dt = the time between the two
// readings, 0 when it is zero, negative or unknown, so max_step_* alone bound
// such steps); and a pose is implausible when a coordinate is not finite or
// beyond max_coordinate_m.
//
// Absolute readings (odometry in the observations-only format) are judged
// against the last accepted reading. When `reset_after` consecutive readings
// are all rejected but agree with each other, the odometry itself jumped (a
// reset of the robot's odometry counter): the gate re-anchors, so that the
// new readings continue from the last accepted pose, and counts a reset.
#pragma once

#include <mrpt/math/TPose3D.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace pmap::config {
class SectionReader;
}

namespace pmap::poses {

/// [Poses] motion limits (doc/configuration.md).
struct MotionLimits {
  double max_speed_mps = 10.0;       ///< fastest plausible translation (m/s)
  double max_turn_rate_dps = 720.0;  ///< fastest plausible rotation (deg/s)
  double max_step_m = 1.0;           ///< translation allowed on top of speed x dt (m)
  double max_step_deg = 90.0;        ///< rotation allowed on top of turn rate x dt (deg)
  double max_coordinate_m = 1e7;     ///< largest plausible |x|, |y|, |z| of a pose (m)
  int reset_after = 5;  ///< consecutive agreeing rejected readings that re-anchor (0: never)

  bool validate(std::string* why) const;
};

struct MotionGateStats {
  std::size_t non_finite = 0;  ///< NaN / Inf coordinates
  std::size_t too_far = 0;     ///< a coordinate beyond max_coordinate_m
  std::size_t too_fast = 0;    ///< a step beyond the limits
  std::size_t resets = 0;      ///< re-anchorings after an odometry jump
  std::size_t dropped() const { return non_finite + too_far + too_fast; }
};

class MotionGate {
 public:
  explicit MotionGate(MotionLimits limits) : limits_(limits) {}

  /// An absolute pose at time `t_s` (NaN: unknown). Returns the pose to use
  /// (the reading, re-anchored after a reset) or nullopt when dropped.
  std::optional<mrpt::math::TPose3D> absolute(double t_s, const mrpt::math::TPose3D& reading);

  /// A relative step (an odometry increment) over `dt_s` seconds (NaN or
  /// <= 0: unknown). True when plausible; counts it otherwise.
  bool increment(double dt_s, const mrpt::math::TPose3D& step);

  const MotionGateStats& stats() const { return stats_; }
  const MotionLimits& limits() const { return limits_; }

  /// One line for a warning, empty when nothing was dropped.
  std::string summary(const std::string& what) const;

 private:
  struct Reading {
    double t;
    mrpt::math::TPose3D pose;
  };
  /// Null when plausible, else the counter to increment.
  std::size_t* implausiblePose(const mrpt::math::TPose3D& p);
  bool plausibleStep(double dt_s, const mrpt::math::TPose3D& from,
                     const mrpt::math::TPose3D& to) const;
  std::optional<mrpt::math::TPose3D> rejectStep(const Reading& r);

  MotionLimits limits_;
  MotionGateStats stats_;
  std::optional<Reading> last_raw_;               ///< last accepted reading, as read
  mrpt::math::TPose3D offset_{0, 0, 0, 0, 0, 0};  ///< re-anchoring: used = offset (+) read
  std::vector<Reading> rejected_;                 ///< consecutive agreeing rejected readings
};

}  // namespace pmap::poses
