// Pinhole cameras. The camera pose is MRPT's optical frame (CObservationImage::
// cameraPose): +Z forward along the optical axis, +X to the image right, +Y
// down. MRPT's "camera looking along robot +X" is CPose3D(x, y, z, -90deg, 0,
// -90deg); turning that about the robot's +Z gives
//   look forward:  yaw -90, pitch 0, roll -90
//   look left:     yaw   0, pitch 0, roll -90   (optical axis = robot +Y)
//   look right:    yaw 180, pitch 0, roll -90   (optical axis = robot -Y)
//   look backward: yaw  90, pitch 0, roll -90
// Pixel centres are at integer coordinates; (cx, cy) = ((W-1)/2, (H-1)/2).
// projectPoint() and pixelRay() are the ideal pinhole; lens distortion, if
// any, is applied to the rendered image (lens_distortion.h).
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>

#include "pmap/sim/pose.h"
#include "pmap/sim/sensor_options.h"

namespace pmap::sim {

struct PinholeIntrinsics {
  int width_px = 640;
  int height_px = 480;
  double fx = 320.0;
  double fy = 320.0;
  double cx = 319.5;
  double cy = 239.5;
  /// k1, k2, p1, p2, k3 (MRPT TCamera::dist order); zeros = no distortion.
  std::array<double, 5> distortion{{0.0, 0.0, 0.0, 0.0, 0.0}};

  /// Square pixels, principal point at the image centre, horizontal FOV in
  /// radians, no distortion.
  static PinholeIntrinsics fromFov(int width_px, int height_px, double hfov_rad);
};

/// The optical-frame pose of a mount on the robot (CPose3D convention, radians).
Pose6D cameraMountPose(const CameraMount& mount);

/// Pixel (u, v) of a world point, or nothing if it lies behind the camera
/// (z <= 1 mm in the optical frame). Points outside the image are returned too.
std::optional<Eigen::Vector2d> projectPoint(const PinholeIntrinsics& k,
                                            const RigidTransform& camera_to_world,
                                            const Eigen::Vector3d& p_world);

/// Ray through pixel (u, v) in the optical frame, scaled to z = 1.
Eigen::Vector3d pixelRay(const PinholeIntrinsics& k, double u, double v);

}  // namespace pmap::sim
