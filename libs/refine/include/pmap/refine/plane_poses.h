// Planes correct poses (issue 15 item 5; the paper's section VII, future
// work): the structure scans' points pull the robot's path towards the
// vertical surfaces the EM assigned them to, jointly with those surfaces'
// planes, while relative-motion priors along the path (the pose graph's
// relative poses) hold the path's shape. doc/poses.md, "Planes correct
// poses".
//
// The correction is a world-frame SE(2) increment per knot (a knot every
// knot_spacing_m of path), linear in time between knots: a robot pose at
// time t is turned by dtheta(t) about its own position and moved by
// (dx, dy)(t). A scan's points move with its pose:
//   p' = R(dtheta) (p - c) + c + d,   c the robot's position.          (P1)
// Residuals, whitened:
//   point on vertical surface w:  (n_w . p'_xy - d_w) / sigma           (P2)
//   knots k, k+1:  the pose-graph edge residual between the corrected
//   knot poses and their relative pose before the correction, with
//   sigma_t = motion_sigma_m_per_m * s + 5 mm and
//   sigma_theta = motion_sigma_deg_per_m * s + 0.05 deg (s: path between). (P3)
// The first knot is held (the gauge); planes are (angle, offset) of a
// vertical plane. Huber loss on (P2).
#pragma once

#include <mrpt/math/TPose3D.h>

#include <Eigen/Core>
#include <vector>

#include "pmap/em/offline_em.h"
#include "pmap/points/point_map.h"
#include "pmap/poses/trajectory.h"
#include "pmap/refine/plane_pose_options.h"

namespace pmap::refine {

/// World-frame corrections at knot times, linear in time between them
/// (held at the ends).
class PoseCorrection {
 public:
  PoseCorrection() = default;
  PoseCorrection(std::vector<double> t, std::vector<Eigen::Vector3d> delta);
  bool empty() const { return t_.empty(); }
  /// (dx, dy, dtheta) at time t.
  Eigen::Vector3d at(double t) const;
  /// The pose taken at time t, corrected (P1): turned about its position.
  mrpt::math::TPose3D apply(double t, const mrpt::math::TPose3D& pose) const;
  const std::vector<double>& times() const { return t_; }
  const std::vector<Eigen::Vector3d>& deltas() const { return delta_; }

 private:
  std::vector<double> t_;
  std::vector<Eigen::Vector3d> delta_;
};

struct PlanePoseResult {
  bool ran = false;  ///< false: fewer than two knots or no point on a vertical surface
  PoseCorrection correction;
  int knots = 0;
  int surfaces = 0;           ///< vertical surfaces in the problem
  std::size_t residuals = 0;  ///< point residuals (P2)
  int iterations = 0;
  double initial_cost = 0.0;
  double final_cost = 0.0;
  double max_shift_m = 0.0;   ///< the largest knot translation
  double max_turn_deg = 0.0;  ///< the largest knot rotation
  double seconds = 0.0;       ///< wall time of the fit (building and solving the problem)
  std::string termination;
};

/// Fits the corrections to `map`'s points and `planar`'s vertical surfaces
/// (assignment per point, as the EM left it). `map` holds the points as the
/// pose stage placed them; `planar` was fitted to them moved by `start` (a
/// previous round's correction, empty the first time), which is where the
/// fit starts. The priors (P3, P4) hold to the pose stage's poses.
PlanePoseResult fitPosesToPlanes(const points::PointMap& map, const em::PlanarMap& planar,
                                 const PlanePoseOptions& options, const PoseCorrection& start = {});

/// Moves every scan of `map` and every pose of `trajectory` by `correction`.
void applyCorrection(const PoseCorrection& correction, points::PointMap& map,
                     poses::Trajectory& trajectory);

}  // namespace pmap::refine
