// Test worlds of wall segments and a 2D laser in them, shared by the pose
// graph's tests (loop closure, path constraints).
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <random>
#include <vector>

#include "pmap/poses/pose_graph.h"

namespace pmap::poses::testing {

struct Segment {
  Eigen::Vector2d a, b;
};

inline double rayHit(const std::vector<Segment>& world, const Eigen::Vector2d& o,
                     const Eigen::Vector2d& d, double max_range) {
  double best = max_range;
  for (const Segment& s : world) {
    const Eigen::Vector2d e = s.b - s.a;
    const double den = d.x() * e.y() - d.y() * e.x();
    if (std::abs(den) < 1e-12) {
      continue;
    }
    const Eigen::Vector2d w = s.a - o;
    const double t = (w.x() * e.y() - w.y() * e.x()) / den;
    const double u = (w.x() * d.y() - w.y() * d.x()) / den;
    if (t > 0 && u >= 0 && u <= 1 && t < best) {
      best = t;
    }
  }
  return best;
}

/// A 181-beam, 180-degree scan from `pose` with `noise_m` range noise, in
/// the robot frame; beams that hit nothing within `max_range_m` are left out.
inline std::vector<Eigen::Vector2d> scan(const std::vector<Segment>& world, const Pose2& pose,
                                         std::mt19937& rng, double noise_m = 0.01,
                                         double max_range_m = 15.0) {
  std::normal_distribution<double> noise(0.0, noise_m);
  std::vector<Eigen::Vector2d> out;
  for (int i = 0; i <= 180; ++i) {
    const double a = (i - 90) * M_PI / 180.0;
    const Eigen::Vector2d d(std::cos(pose.theta + a), std::sin(pose.theta + a));
    const double r = rayHit(world, {pose.x, pose.y}, d, max_range_m);
    if (r < max_range_m) {
      out.emplace_back((r + noise(rng)) * std::cos(a), (r + noise(rng)) * std::sin(a));
    }
  }
  return out;
}

/// The four walls of a box.
inline void addBox(std::vector<Segment>& w, double x0, double y0, double x1, double y1) {
  w.push_back({{x0, y0}, {x1, y0}});
  w.push_back({{x1, y0}, {x1, y1}});
  w.push_back({{x1, y1}, {x0, y1}});
  w.push_back({{x0, y1}, {x0, y0}});
}

}  // namespace pmap::poses::testing
