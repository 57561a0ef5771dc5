#include "pmap/texture/camera_frame.h"

#include <mrpt/poses/CPose3D.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgcodecs.hpp>

#include "pmap/common/error.h"

namespace pmap::texture {

std::optional<Eigen::Vector2d> CameraFrame::projectCamera(const Eigen::Vector3d& c) const {
  if (c.z() <= 1e-6) {
    return std::nullopt;
  }
  const double x = c.x() / c.z();
  const double y = c.y() / c.z();
  // Radial-tangential distortion (k1, k2, p1, p2, k3), as MRPT's TCamera.
  const double r2 = x * x + y * y;
  const double radial = 1.0 + r2 * (dist[0] + r2 * (dist[1] + r2 * dist[4]));
  const double xd = x * radial + 2.0 * dist[2] * x * y + dist[3] * (r2 + 2.0 * x * x);
  const double yd = y * radial + dist[2] * (r2 + 2.0 * y * y) + 2.0 * dist[3] * x * y;
  return Eigen::Vector2d(K(0, 0) * xd + K(0, 2), K(1, 1) * yd + K(1, 2));
}

CameraFrame CameraFrame::scaled(double factor) const {
  CameraFrame f = *this;
  f.width = std::max(1, static_cast<int>(std::lround(width * factor)));
  f.height = std::max(1, static_cast<int>(std::lround(height * factor)));
  const double sx = static_cast<double>(f.width) / width;
  const double sy = static_cast<double>(f.height) / height;
  f.scale = scale * sx;
  f.K(0, 0) *= sx;

  f.K(1, 1) *= sy;
  // Pixel centres at integer coordinates: x' + 0.5 = s (x + 0.5).
  f.K(0, 2) = sx * (K(0, 2) + 0.5) - 0.5;
  f.K(1, 2) = sy * (K(1, 2) + 0.5) - 0.5;
  return f;
}

CameraFrame makeFrame(const mrpt::obs::CObservationImage::Ptr& obs,
                      const mrpt::poses::CPose3D& robot_pose) {
  CameraFrame f;
  f.obs = obs;
  f.timestamp = mrpt::Clock::toDouble(obs->timestamp);
  f.label = obs->sensorLabel;
  const mrpt::img::TCamera& cam = obs->cameraParams;
  f.K = cam.intrinsicParams.asEigen();
  for (int k = 0; k < 5; ++k) {
    f.dist[static_cast<std::size_t>(k)] = cam.dist[static_cast<std::size_t>(k)];
  }
  f.width = static_cast<int>(cam.ncols);
  f.height = static_cast<int>(cam.nrows);
  const mrpt::poses::CPose3D world_camera = robot_pose + obs->cameraPose;
  Eigen::Isometry3d camera_to_world = Eigen::Isometry3d::Identity();
  camera_to_world.linear() = world_camera.getRotationMatrix().asEigen();
  camera_to_world.translation() =
      Eigen::Vector3d(world_camera.x(), world_camera.y(), world_camera.z());
  f.world_to_camera = camera_to_world.inverse();
  f.centre = camera_to_world.translation();
  return f;
}

std::filesystem::path externalImagesDir(const std::filesystem::path& rawlog) {
  // MRPT 2.5.8's CRawlog::detectImagesDirectory joins the folder and the
  // name without a separator ("/data" + "run_Images"), so its own candidates
  // never exist; the same search, with the separator.
  const std::filesystem::path dir = rawlog.parent_path();
  const std::string stem = rawlog.stem().string();
  for (const char* suffix : {"_Images", "_images", "_IMAGES"}) {
    const std::filesystem::path candidate = dir / (stem + suffix);
    if (std::filesystem::is_directory(candidate)) {
      return candidate;
    }
  }
  return dir / "Images";
}

cv::Mat loadFrameImage(const CameraFrame& frame, const std::filesystem::path& images_dir) {
  const mrpt::img::CImage& img = frame.obs->image;
  if (!img.isExternallyStored()) {
    cv::Mat m = img.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY).clone();
    if (m.channels() == 1) {
      cv::Mat bgr;
      cv::merge(std::vector<cv::Mat>{m, m, m}, bgr);
      return bgr;
    }
    return m;
  }
  std::filesystem::path file = img.getExternalStorageFile();
  if (file.is_relative()) {
    file = images_dir / file;
  }
  cv::Mat m = cv::imread(file.string(), cv::IMREAD_COLOR);
  if (m.empty()) {
    throw InputError(file.string() + ": external image of " + frame.label +
                     " cannot be read (MRPT looks in " + images_dir.string() + ")");
  }
  return m;
}

}  // namespace pmap::texture
