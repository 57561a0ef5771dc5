#include "pmap/sim/camera_model.h"

#include <cmath>

namespace pmap::sim {

PinholeIntrinsics PinholeIntrinsics::fromFov(int width_px, int height_px, double hfov_rad) {
  PinholeIntrinsics k;
  k.width_px = width_px;
  k.height_px = height_px;
  k.fx = 0.5 * width_px / std::tan(0.5 * hfov_rad);
  k.fy = k.fx;
  k.cx = 0.5 * (width_px - 1);
  k.cy = 0.5 * (height_px - 1);
  return k;
}

Pose6D cameraMountPose(const CameraMount& mount) {
  double yaw_deg = 0.0;
  if (mount.look == "forward") {
    yaw_deg = -90.0;
  } else if (mount.look == "right") {
    yaw_deg = 180.0;
  } else if (mount.look == "backward") {
    yaw_deg = 90.0;
  }
  return pose6DFromDegrees(
      {mount.position_m[0], mount.position_m[1], mount.position_m[2], yaw_deg, 0.0, -90.0});
}

std::optional<Eigen::Vector2d> projectPoint(const PinholeIntrinsics& k,
                                            const RigidTransform& camera_to_world,
                                            const Eigen::Vector3d& p_world) {
  const Eigen::Vector3d p = camera_to_world.applyInverse(p_world);
  if (p.z() <= 1e-3) {
    return std::nullopt;
  }
  return Eigen::Vector2d(k.cx + k.fx * p.x() / p.z(), k.cy + k.fy * p.y() / p.z());
}

Eigen::Vector3d pixelRay(const PinholeIntrinsics& k, double u, double v) {
  return Eigen::Vector3d((u - k.cx) / k.fx, (v - k.cy) / k.fy, 1.0);
}

}  // namespace pmap::sim
