// Test helpers: camera frames looking at textured planes, and images
// rendered by ray casting (independent of libs/texture's sampling code).
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "pmap/products/map_model.h"
#include "pmap/texture/camera_frame.h"

namespace pmap::texture::test {

/// A pinhole camera (640 x 480, f = 320, no distortion) at `centre` looking
/// along `forward` with image rows going along -`up`.
inline CameraFrame lookAt(const Eigen::Vector3d& centre, const Eigen::Vector3d& forward,
                          const Eigen::Vector3d& up, const std::string& label, int width = 640,
                          int height = 480) {
  CameraFrame f;
  f.label = label;
  f.width = width;
  f.height = height;
  f.K << 320, 0, (width - 1) / 2.0, 0, 320, (height - 1) / 2.0, 0, 0, 1;
  const Eigen::Vector3d z = forward.normalized();
  const Eigen::Vector3d x = z.cross(up).normalized();  // image right
  const Eigen::Vector3d y = z.cross(x);                // image down
  Eigen::Matrix3d R;                                   // camera -> world columns
  R.col(0) = x, R.col(1) = y, R.col(2) = z;
  Eigen::Isometry3d camera_to_world = Eigen::Isometry3d::Identity();
  camera_to_world.linear() = R;
  camera_to_world.translation() = centre;
  f.world_to_camera = camera_to_world.inverse();
  f.centre = centre;
  return f;
}

/// A textured planar rectangle of the test world: colour(s, t) over its
/// (s, t) in [0, 1]^2 (map_model.h's convention).
struct PaintedQuad {
  products::TexturedQuad quad;
  std::function<cv::Vec3f(double s, double t)> colour;
};

/// Renders the quads seen by `f` (nearest hit per pixel, pixel centres);
/// `background` elsewhere. `gain` scales the colours (exposure).
inline cv::Mat render(const CameraFrame& f, const std::vector<PaintedQuad>& quads, float gain = 1.f,
                      cv::Vec3b background = {40, 40, 40}) {
  cv::Mat img(f.height, f.width, CV_8UC3, background);
  const Eigen::Isometry3d camera_to_world = f.world_to_camera.inverse();
  for (int v = 0; v < f.height; ++v) {
    for (int u = 0; u < f.width; ++u) {
      const Eigen::Vector3d ray_cam((u - f.K(0, 2)) / f.K(0, 0), (v - f.K(1, 2)) / f.K(1, 1), 1);
      const Eigen::Vector3d d = camera_to_world.linear() * ray_cam;
      double best = 1e300;
      for (const PaintedQuad& q : quads) {
        const auto& c = q.quad.corners;
        const Eigen::Vector3d eu = c[1] - c[0], ev = c[3] - c[0];
        const Eigen::Vector3d n = eu.cross(ev);
        const double denom = n.dot(d);
        if (std::abs(denom) < 1e-12)
          continue;
        const double lambda = n.dot(c[0] - f.centre) / denom;
        if (lambda <= 0 || lambda >= best)
          continue;
        const Eigen::Vector3d p = f.centre + lambda * d - c[0];
        const double s = p.dot(eu) / eu.squaredNorm(), t = p.dot(ev) / ev.squaredNorm();
        if (s < 0 || s > 1 || t < 0 || t > 1)
          continue;
        best = lambda;
        const cv::Vec3f col = q.colour(s, t) * gain;
        img.at<cv::Vec3b>(v, u) =
            cv::Vec3b(cv::saturate_cast<uchar>(col[0]), cv::saturate_cast<uchar>(col[1]),
                      cv::saturate_cast<uchar>(col[2]));
      }
    }
  }
  return img;
}

/// A wall quad in the plane y = y0 from x0 to x1 (s along +x), z from 0 to
/// height (t along +z), seen from -y (its normal points to -y).
inline products::TexturedQuad wallQuad(int id, double x0, double x1, double y0, double height) {
  products::TexturedQuad q;
  q.surface_id = id;
  q.corners = {Eigen::Vector3d(x0, y0, 0), Eigen::Vector3d(x1, y0, 0),
               Eigen::Vector3d(x1, y0, height), Eigen::Vector3d(x0, y0, height)};
  q.normal = -Eigen::Vector3d::UnitY();
  return q;
}

/// A smooth but detailed pattern (periods of a few centimetres), BGR 0..255.
inline cv::Vec3f pattern(double s_m, double t_m) {
  const double a = std::sin(2 * M_PI * s_m / 0.11) * std::cos(2 * M_PI * t_m / 0.07);
  const double b = std::sin(2 * M_PI * (s_m + t_m) / 0.23);
  return cv::Vec3f(static_cast<float>(128 + 60 * a), static_cast<float>(128 + 50 * b),
                   static_cast<float>(128 + 40 * a * b));
}

/// PSNR (dB) between two BGR 8-bit images of the same size.
inline double psnr(const cv::Mat& a, const cv::Mat& b) {
  const double mse = cv::norm(a, b, cv::NORM_L2SQR) / (a.total() * a.channels());
  return mse > 0 ? 10 * std::log10(255.0 * 255.0 / mse) : 99.0;
}

}  // namespace pmap::texture::test
