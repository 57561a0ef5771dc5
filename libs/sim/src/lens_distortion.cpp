#include "pmap/sim/lens_distortion.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "pmap/common/error.h"

namespace pmap::sim {
namespace {

constexpr double kMaxCanvasScale = 3.0;  // the render canvas may be at most 3x the image per axis

bool fail(std::string* why, const std::string& message) {
  if (why != nullptr) {
    *why = message;
  }
  return false;
}

bool isZero(const DistortionCoefficients& d) {
  return std::all_of(d.begin(), d.end(), [](double c) { return c == 0.0; });
}

/// Distortion and its Jacobian d(x_d, y_d) / d(x, y).
Eigen::Vector2d distortWithJacobian(const DistortionCoefficients& d, const Eigen::Vector2d& p,
                                    Eigen::Matrix2d& jac) {
  const double k1 = d[0], k2 = d[1], p1 = d[2], p2 = d[3], k3 = d[4];
  const double x = p.x(), y = p.y();
  const double r2 = x * x + y * y;
  const double radial = 1.0 + r2 * (k1 + r2 * (k2 + r2 * k3));
  const double dradial = k1 + r2 * (2.0 * k2 + 3.0 * k3 * r2);  // d radial / d r2
  jac(0, 0) = radial + 2.0 * x * x * dradial + 2.0 * p1 * y + 6.0 * p2 * x;
  jac(0, 1) = 2.0 * x * y * dradial + 2.0 * p1 * x + 2.0 * p2 * y;
  jac(1, 0) = jac(0, 1);
  jac(1, 1) = radial + 2.0 * y * y * dradial + 6.0 * p1 * y + 2.0 * p2 * x;
  return Eigen::Vector2d(x * radial + 2.0 * p1 * x * y + p2 * (r2 + 2.0 * x * x),
                         y * radial + p1 * (r2 + 2.0 * y * y) + 2.0 * p2 * x * y);
}

/// Normalised coordinates of the outer edges of the image's border pixels.
std::vector<Eigen::Vector2d> borderPoints(const PinholeIntrinsics& k) {
  std::vector<Eigen::Vector2d> out;
  const double u0 = -0.5, u1 = k.width_px - 0.5, v0 = -0.5, v1 = k.height_px - 0.5;
  const int steps = 64;
  for (int i = 0; i <= steps; ++i) {
    const double a = static_cast<double>(i) / steps;
    for (const Eigen::Vector2d& px :
         {Eigen::Vector2d(u0 + a * (u1 - u0), v0), Eigen::Vector2d(u0 + a * (u1 - u0), v1),
          Eigen::Vector2d(u0, v0 + a * (v1 - v0)), Eigen::Vector2d(u1, v0 + a * (v1 - v0))}) {
      out.emplace_back((px.x() - k.cx) / k.fx, (px.y() - k.cy) / k.fy);
    }
  }
  return out;
}

}  // namespace

Eigen::Vector2d distortNormalised(const DistortionCoefficients& d, const Eigen::Vector2d& xy) {
  Eigen::Matrix2d unused;
  return distortWithJacobian(d, xy, unused);
}

std::optional<Eigen::Vector2d> undistortNormalised(const DistortionCoefficients& d,
                                                   const Eigen::Vector2d& xy_d) {
  Eigen::Vector2d p = xy_d;
  for (int iteration = 0; iteration < 50; ++iteration) {
    Eigen::Matrix2d jac;
    const Eigen::Vector2d residual = distortWithJacobian(d, p, jac) - xy_d;
    if (residual.norm() < 1e-12 * (1.0 + xy_d.norm())) {
      return p;
    }
    if (!(std::abs(jac.determinant()) > 1e-12)) {
      return std::nullopt;
    }
    p -= jac.partialPivLu().solve(residual);
    if (!p.allFinite()) {
      return std::nullopt;
    }
  }
  return std::nullopt;
}

bool distortionIsUsable(const PinholeIntrinsics& k, const DistortionCoefficients& d,
                        std::string* why) {
  if (isZero(d)) {
    return true;
  }
  double r_corner = 0.0;
  for (const Eigen::Vector2d& p : borderPoints(k)) {
    r_corner = std::max(r_corner, p.norm());
  }
  // The radial profile g(r) = r (1 + k1 r^2 + k2 r^4 + k3 r^6) must rise until
  // it passes the corners (with 5 % margin), else the image folds over.
  auto profile = [&d](double r) {
    const double r2 = r * r;
    return r * (1.0 + r2 * (d[0] + r2 * (d[1] + r2 * d[4])));
  };
  auto slope = [&d](double r) {
    const double r2 = r * r;
    return 1.0 + r2 * (3.0 * d[0] + r2 * (5.0 * d[1] + 7.0 * d[4] * r2));
  };
  for (double r = 0.0; profile(r) < 1.05 * r_corner; r += 1e-3 * r_corner) {
    if (!(slope(r) > 0.05) || r > kMaxCanvasScale * r_corner) {
      return fail(why,
                  "lens.distortion: the radial distortion folds over or does not reach the "
                  "image corners (k1, k2, k3 too strong for this field of view)");
    }
  }
  const double half_w = 0.5 * k.width_px / k.fx, half_h = 0.5 * k.height_px / k.fy;
  for (const Eigen::Vector2d& p : borderPoints(k)) {
    const auto ideal = undistortNormalised(d, p);
    if (!ideal) {
      return fail(why, "lens.distortion: cannot invert the distortion at the image border");
    }
    if (std::abs(ideal->x()) > kMaxCanvasScale * half_w ||
        std::abs(ideal->y()) > kMaxCanvasScale * half_h) {
      return fail(why, "lens.distortion: the undistorted field of view exceeds 3x the image");
    }
  }
  return true;
}

LensWarp::LensWarp(const PinholeIntrinsics& output) : render_(output) {
  render_.distortion = DistortionCoefficients{};
  if (isZero(output.distortion)) {
    return;
  }
  std::string why;
  if (!distortionIsUsable(output, output.distortion, &why)) {
    throw ConfigError("cameras: " + why);
  }
  // Ideal (pinhole) pixel of every output pixel, relative to the principal point.
  cv::Mat du(output.height_px, output.width_px, CV_32FC1);
  cv::Mat dv(output.height_px, output.width_px, CV_32FC1);
  double umin = std::numeric_limits<double>::infinity(), vmin = umin, umax = -umin, vmax = -umin;
  for (int v = 0; v < output.height_px; ++v) {
    for (int u = 0; u < output.width_px; ++u) {
      const Eigen::Vector2d xd((u - output.cx) / output.fx, (v - output.cy) / output.fy);
      const auto ideal = undistortNormalised(output.distortion, xd);
      if (!ideal) {
        throw ConfigError("cameras: lens.distortion: cannot invert the distortion at pixel (" +
                          std::to_string(u) + ", " + std::to_string(v) + ")");
      }
      const double iu = output.fx * ideal->x(), iv = output.fy * ideal->y();
      du.at<float>(v, u) = static_cast<float>(iu);
      dv.at<float>(v, u) = static_cast<float>(iv);
      umin = std::min(umin, iu);
      umax = std::max(umax, iu);
      vmin = std::min(vmin, iv);
      vmax = std::max(vmax, iv);
    }
  }
  // Canvas with a 2-pixel margin for the bilinear footprint.
  render_.cx = std::ceil(-umin) + 2.0;
  render_.cy = std::ceil(-vmin) + 2.0;
  render_.width_px = static_cast<int>(render_.cx + std::ceil(umax)) + 3;
  render_.height_px = static_cast<int>(render_.cy + std::ceil(vmax)) + 3;
  map_u_ = du + static_cast<float>(render_.cx);
  map_v_ = dv + static_cast<float>(render_.cy);
}

cv::Mat LensWarp::apply(const cv::Mat& render) const {
  if (map_u_.empty()) {
    return render;
  }
  cv::Mat out;
  cv::remap(render, out, map_u_, map_v_, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  return out;
}

}  // namespace pmap::sim
