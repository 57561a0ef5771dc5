// Trajectory error of estimated poses against ground truth.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "pmap/poses/trajectory.h"

namespace pmap::eval {

/// A rigid 2D motion (rotation about z, translation in xy) as a 3D isometry.
struct Rigid2D {
  double yaw = 0;
  Eigen::Vector2d t = Eigen::Vector2d::Zero();
  Eigen::Vector3d apply(const Eigen::Vector3d& p) const;
  /// The rotation only (for directions such as normals).
  Eigen::Vector3d rotate(const Eigen::Vector3d& v) const;
  double applyYaw(double y) const { return y + yaw; }
};

/// Least-squares rigid 2D alignment of a onto b (Kabsch/Umeyama without
/// scale): argmin sum |R a_i + t - b_i|^2. Needs at least 2 distinct points
/// for a unique rotation (otherwise yaw = 0).
Rigid2D alignRigid2D(const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b);

struct PoseErrors {
  std::size_t matched = 0;      ///< estimated poses with a ground-truth pose at their time
  double ate_m = 0;             ///< RMS position error after the best rigid 2D alignment
  double ate_first_pose_m = 0;  ///< RMS error with frames tied at the first pose, no fitting
  double final_error_m = 0;     ///< position error of the last pose (after alignment)
  double max_error_m = 0;       ///< largest position error (after alignment)
  double yaw_rms_deg = 0;       ///< RMS heading error (after alignment)
  Rigid2D alignment;            ///< estimated frame -> ground-truth frame
};

/// Compares every estimated pose with the ground truth interpolated at its
/// timestamp (poses outside the ground truth's span are skipped).
PoseErrors comparePoses(const poses::Trajectory& estimated, const poses::Trajectory& truth);

}  // namespace pmap::eval
