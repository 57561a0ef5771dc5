// The robot's true trajectory: the path's waypoints joined by straight
// segments and circular arcs at the corners, driven at constant speed. Yaw is
// continuous and its rate is bounded by speed / radius <= max_yaw_rate.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "pmap/sim/pose.h"
#include "pmap/sim/world_spec.h"

namespace pmap::sim {

class Trajectory {
 public:
  /// Throws ConfigError (naming `file` and "path") for U-turns, coincident
  /// waypoints and segments too short for the corner radius.
  Trajectory(const PathSpec& spec, const std::string& file);

  double length_m() const { return length_m_; }
  double speed_m_s() const { return speed_m_s_; }
  double duration_s() const { return length_m_ / speed_m_s_; }
  /// The radius used for every corner, metres.
  double cornerRadius_m() const { return radius_m_; }

  /// Pose after driving `s_m` metres (clamped to [0, length]).
  Pose2D poseAtDistance(double s_m) const;
  /// Pose `t_s` seconds after the start (clamped).
  Pose2D poseAtTime(double t_s) const { return poseAtDistance(t_s * speed_m_s_); }

 private:
  struct Piece {
    double start_s = 0.0;  ///< arc length at the piece's start
    double length = 0.0;
    bool arc = false;
    Eigen::Vector2d start = Eigen::Vector2d::Zero();   ///< line start
    Eigen::Vector2d dir = Eigen::Vector2d::UnitX();    ///< line direction
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();  ///< arc centre
    double heading0 = 0.0;                             ///< heading at the piece's start
    double turn = 1.0;                                 ///< +1 left (counter-clockwise), -1 right
  };
  void addLine(const Eigen::Vector2d& a, const Eigen::Vector2d& b);

  std::vector<Piece> pieces_;
  double length_m_ = 0.0;
  double speed_m_s_ = 0.4;
  double radius_m_ = 0.0;
};

}  // namespace pmap::sim
