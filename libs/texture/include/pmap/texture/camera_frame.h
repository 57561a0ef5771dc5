// A camera image placed in the world: intrinsics and distortion from the
// observation's calibration, the optical frame's pose from the robot pose
// interpolated at the image's timestamp composed with the camera's pose on
// the robot (MRPT's optical frame: +Z forward, +X right, +Y down).
#pragma once

#include <mrpt/obs/CObservationImage.h>

#include <Eigen/Geometry>
#include <array>
#include <filesystem>
#include <opencv2/core.hpp>
#include <optional>
#include <string>

namespace pmap::texture {

struct CameraFrame {
  double timestamp = 0;
  std::string label;
  Eigen::Matrix3d K = Eigen::Matrix3d::Identity();
  std::array<double, 5> dist{};  ///< k1 k2 p1 p2 k3 (radial-tangential)
  int width = 0;
  int height = 0;
  double scale = 1.0;  ///< of this image relative to the recorded one (thumbnails < 1)

  Eigen::Isometry3d world_to_camera = Eigen::Isometry3d::Identity();
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< optical centre in the world
  mrpt::obs::CObservationImage::Ptr obs;             ///< the observation (image maybe external)

  /// Pixel coordinates of a world point; empty behind the camera.
  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& world) const {
    return projectCamera(world_to_camera * world);
  }
  /// Pixel coordinates of a point in the camera frame (lens distortion
  /// applied); empty behind the camera.
  std::optional<Eigen::Vector2d> projectCamera(const Eigen::Vector3d& c) const;
  /// The same frame for the image scaled by `factor` (thumbnails).
  CameraFrame scaled(double factor) const;
};

/// The frame of `obs` with the robot at `robot_pose` (world).
CameraFrame makeFrame(const mrpt::obs::CObservationImage::Ptr& obs,
                      const mrpt::poses::CPose3D& robot_pose);

/// Loads the frame's image as BGR 8-bit. External images are found as MRPT
/// does: relative names live in `images_dir` (the rawlog's "<name>_Images"
/// folder). Throws InputError naming the file when it cannot be read.
cv::Mat loadFrameImage(const CameraFrame& frame, const std::filesystem::path& images_dir);

/// The folder MRPT (RawLogViewer, rawlog-edit) looks in for a rawlog's
/// external images (as mrpt::obs::CRawlog::detectImagesDirectory means to): the first
/// existing of "<rawlog without extension>_Images", "_images", "_IMAGES"
/// beside it, else "Images" beside it.
std::filesystem::path externalImagesDir(const std::filesystem::path& rawlog);

}  // namespace pmap::texture
