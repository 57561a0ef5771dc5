#include "pmap/sim/trajectory.h"

#include <algorithm>
#include <cmath>

#include "pmap/common/error.h"

namespace pmap::sim {
namespace {

Eigen::Vector2d leftOf(const Eigen::Vector2d& d) {
  return Eigen::Vector2d(-d.y(), d.x());
}

Eigen::Vector2d headingDir(double h) {
  return Eigen::Vector2d(std::cos(h), std::sin(h));
}

}  // namespace

void Trajectory::addLine(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const double len = (b - a).norm();
  if (len < 1e-12) {
    return;
  }
  Piece p;
  p.start_s = length_m_;
  p.length = len;
  p.start = a;
  p.dir = (b - a) / len;
  p.heading0 = std::atan2(p.dir.y(), p.dir.x());
  pieces_.push_back(p);
  length_m_ += len;
}

Trajectory::Trajectory(const PathSpec& spec, const std::string& file) : speed_m_s_(spec.speed_m_s) {
  auto fail = [&](const std::string& m) { throw ConfigError(file + ": path: " + m); };
  const std::vector<Eigen::Vector2d>& w = spec.waypoints;
  const std::size_t n = w.size();
  radius_m_ =
      std::max(spec.corner_radius_m, spec.speed_m_s / (spec.max_yaw_rate_deg_s * M_PI / 180.0));
  std::vector<Eigen::Vector2d> dirs;
  std::vector<double> lengths;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    lengths.push_back((w[i + 1] - w[i]).norm());
    if (lengths.back() < 1e-6) {
      fail("waypoints " + std::to_string(i) + " and " + std::to_string(i + 1) + " coincide");
    }
    dirs.push_back((w[i + 1] - w[i]) / lengths.back());
  }
  std::vector<double> turn(n, 0.0);     // signed turn angle at each waypoint
  std::vector<double> tangent(n, 0.0);  // distance from the waypoint to the arc ends
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const Eigen::Vector2d& a = dirs[i - 1];
    const Eigen::Vector2d& b = dirs[i];
    turn[i] = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    if (std::abs(turn[i]) > 179.0 * M_PI / 180.0) {
      fail("waypoint " + std::to_string(i) + " is a U-turn (turns must be below 179 degrees)");
    }
    tangent[i] = radius_m_ * std::tan(0.5 * std::abs(turn[i]));
  }
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (tangent[i] + tangent[i + 1] > lengths[i] + 1e-9) {
      fail("segment " + std::to_string(i) + " (" + std::to_string(lengths[i]) +
           " m) is too short for corners of radius " + std::to_string(radius_m_) + " m");
    }
  }
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const Eigen::Vector2d line_end = w[i + 1] - tangent[i + 1] * dirs[i];
    addLine(w[i] + tangent[i] * dirs[i], line_end);
    if (i + 2 < n && std::abs(turn[i + 1]) > 1e-12) {
      Piece arc;
      arc.arc = true;
      arc.start_s = length_m_;
      arc.length = radius_m_ * std::abs(turn[i + 1]);
      arc.turn = turn[i + 1] > 0.0 ? 1.0 : -1.0;
      arc.heading0 = std::atan2(dirs[i].y(), dirs[i].x());
      arc.centre = line_end + arc.turn * radius_m_ * leftOf(dirs[i]);
      pieces_.push_back(arc);
      length_m_ += arc.length;
    }
  }
}

Pose2D Trajectory::poseAtDistance(double s_m) const {
  const double s = std::clamp(s_m, 0.0, length_m_);
  auto it = std::upper_bound(pieces_.begin(), pieces_.end(), s,
                             [](double v, const Piece& p) { return v < p.start_s; });
  const Piece& p = it == pieces_.begin() ? pieces_.front() : *(it - 1);
  const double local = s - p.start_s;
  if (!p.arc) {
    const Eigen::Vector2d q = p.start + local * p.dir;
    return Pose2D{q.x(), q.y(), wrapAngle(p.heading0)};
  }
  const double heading = p.heading0 + p.turn * local / radius_m_;
  const Eigen::Vector2d q = p.centre - p.turn * radius_m_ * leftOf(headingDir(heading));
  return Pose2D{q.x(), q.y(), wrapAngle(heading)};
}

}  // namespace pmap::sim
