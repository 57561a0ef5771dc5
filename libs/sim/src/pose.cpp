#include "pmap/sim/pose.h"

#include <cmath>

namespace pmap::sim {

Eigen::Matrix3d rotationX(double a) {
  const double c = std::cos(a);
  const double s = std::sin(a);
  Eigen::Matrix3d r;
  r << 1.0, 0.0, 0.0,  //
      0.0, c, -s,      //
      0.0, s, c;
  return r;
}

Eigen::Matrix3d rotationY(double a) {
  const double c = std::cos(a);
  const double s = std::sin(a);
  Eigen::Matrix3d r;
  r << c, 0.0, s,     //
      0.0, 1.0, 0.0,  //
      -s, 0.0, c;
  return r;
}

Eigen::Matrix3d rotationZ(double a) {
  const double c = std::cos(a);
  const double s = std::sin(a);
  Eigen::Matrix3d r;
  r << c, -s, 0.0,  //
      s, c, 0.0,    //
      0.0, 0.0, 1.0;
  return r;
}

Eigen::Matrix3d rotationYawPitchRoll(double yaw, double pitch, double roll) {
  const Eigen::Matrix3d r = rotationZ(yaw) * rotationY(pitch) * rotationX(roll);
  return r;
}

RigidTransform toTransform(const Pose6D& p) {
  RigidTransform t;
  t.rotation = rotationYawPitchRoll(p.yaw, p.pitch, p.roll);
  t.translation = Eigen::Vector3d(p.x, p.y, p.z);
  return t;
}

RigidTransform toTransform(const Pose2D& p) {
  RigidTransform t;
  t.rotation = rotationZ(p.yaw);
  t.translation = Eigen::Vector3d(p.x, p.y, 0.0);
  return t;
}

RigidTransform compose(const RigidTransform& a, const RigidTransform& b) {
  RigidTransform t;
  t.rotation = a.rotation * b.rotation;
  t.translation = a.rotation * b.translation + a.translation;
  return t;
}

Pose2D compose(const Pose2D& a, const Pose2D& b) {
  const double c = std::cos(a.yaw);
  const double s = std::sin(a.yaw);
  return Pose2D{a.x + c * b.x - s * b.y, a.y + s * b.x + c * b.y, wrapAngle(a.yaw + b.yaw)};
}

Pose2D between(const Pose2D& from, const Pose2D& to) {
  const double c = std::cos(from.yaw);
  const double s = std::sin(from.yaw);
  const double dx = to.x - from.x;
  const double dy = to.y - from.y;
  return Pose2D{c * dx + s * dy, -s * dx + c * dy, wrapAngle(to.yaw - from.yaw)};
}

double wrapAngle(double a) {
  double w = std::remainder(a, 2.0 * M_PI);  // [-pi, pi]
  if (w <= -M_PI) {
    w += 2.0 * M_PI;
  }
  return w;
}

Pose6D pose6DFromDegrees(const std::array<double, 6>& v) {
  return Pose6D{v[0], v[1], v[2], degToRad(v[3]), degToRad(v[4]), degToRad(v[5])};
}

}  // namespace pmap::sim
