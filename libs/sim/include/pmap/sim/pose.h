// The simulator's own pose algebra (Eigen only; it must not share code with the
// mapper). Conventions follow MRPT's CPose3D so that the two can be checked
// against each other in the tests: R = Rz(yaw) * Ry(pitch) * Rx(roll), angles in
// radians; positive pitch turns +X towards -Z ("nose down").
#pragma once

#include <Eigen/Core>
#include <array>

namespace pmap::sim {

/// A planar robot pose: metres, radians (yaw about +Z).
struct Pose2D {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;
};

/// A 6-DoF pose in MRPT's CPose3D parametrisation: metres, radians.
struct Pose6D {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
  double yaw = 0.0;
  double pitch = 0.0;
  double roll = 0.0;
};

/// x_parent = rotation * x_child + translation.
struct RigidTransform {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();

  Eigen::Vector3d apply(const Eigen::Vector3d& p) const { return rotation * p + translation; }
  Eigen::Vector3d applyInverse(const Eigen::Vector3d& p) const {
    return rotation.transpose() * (p - translation);
  }
};

Eigen::Matrix3d rotationX(double angle_rad);
Eigen::Matrix3d rotationY(double angle_rad);
Eigen::Matrix3d rotationZ(double angle_rad);
/// Rz(yaw) * Ry(pitch) * Rx(roll), MRPT's CPose3D convention.
Eigen::Matrix3d rotationYawPitchRoll(double yaw_rad, double pitch_rad, double roll_rad);

RigidTransform toTransform(const Pose6D& pose);
/// The robot frame of a planar pose (z = pitch = roll = 0).
RigidTransform toTransform(const Pose2D& pose);
/// a (+) b: the frame b given in frame a, expressed in a's parent.
RigidTransform compose(const RigidTransform& a, const RigidTransform& b);

/// Planar composition a (+) b.
Pose2D compose(const Pose2D& a, const Pose2D& b);
/// The pose of `to` seen from `from`: from^-1 (+) to.
Pose2D between(const Pose2D& from, const Pose2D& to);

/// Wraps to (-pi, pi].
double wrapAngle(double angle_rad);

constexpr double degToRad(double deg) {
  return deg * (M_PI / 180.0);
}
constexpr double radToDeg(double rad) {
  return rad * (180.0 / M_PI);
}

/// [x, y, z (m), yaw, pitch, roll (deg)] -> Pose6D (radians).
Pose6D pose6DFromDegrees(const std::array<double, 6>& xyz_m_ypr_deg);

}  // namespace pmap::sim
