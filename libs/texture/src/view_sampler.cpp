#include "pmap/texture/view_sampler.h"

#include <array>

namespace pmap::texture {

cv::Vec3f sampleBilinear(const cv::Mat& bgr, double x, double y) {
  const int x0 = std::clamp(static_cast<int>(std::floor(x)), 0, bgr.cols - 1);
  const int y0 = std::clamp(static_cast<int>(std::floor(y)), 0, bgr.rows - 1);
  const int x1 = std::min(bgr.cols - 1, x0 + 1), y1 = std::min(bgr.rows - 1, y0 + 1);
  const float fx = static_cast<float>(std::clamp(x - x0, 0.0, 1.0));
  const float fy = static_cast<float>(std::clamp(y - y0, 0.0, 1.0));
  const cv::Vec3b* r0 = bgr.ptr<cv::Vec3b>(y0);
  const cv::Vec3b* r1 = bgr.ptr<cv::Vec3b>(y1);
  cv::Vec3f out;
  for (int k = 0; k < 3; ++k) {
    out[k] = (1 - fy) * ((1 - fx) * r0[x0][k] + fx * r0[x1][k]) +
             fy * ((1 - fx) * r1[x0][k] + fx * r1[x1][k]);
  }
  return out;
}

namespace {

// Keys' cubic convolution kernel (a = -0.5): weights of the 4 taps at
// offsets -1, 0, 1, 2 from floor(x), for the fraction t in [0, 1).
std::array<float, 4> keysWeights(float t) {
  constexpr float a = -0.5f;
  auto near = [](float d) { return ((a + 2) * d - (a + 3)) * d * d + 1; };       // |d| <= 1
  auto far = [](float d) { return ((a * d - 5 * a) * d + 8 * a) * d - 4 * a; };  // 1 < |d| < 2
  return {far(1 + t), near(t), near(1 - t), far(2 - t)};
}

}  // namespace

cv::Vec3f sampleBicubic(const cv::Mat& bgr, double x, double y) {
  const int x0 = static_cast<int>(std::floor(x));
  const int y0 = static_cast<int>(std::floor(y));
  const std::array<float, 4> wx = keysWeights(static_cast<float>(x - x0));
  const std::array<float, 4> wy = keysWeights(static_cast<float>(y - y0));
  cv::Vec3f out(0, 0, 0);
  for (int j = 0; j < 4; ++j) {
    const cv::Vec3b* row = bgr.ptr<cv::Vec3b>(std::clamp(y0 - 1 + j, 0, bgr.rows - 1));
    cv::Vec3f acc(0, 0, 0);
    for (int i = 0; i < 4; ++i) {
      const cv::Vec3b& p = row[std::clamp(x0 - 1 + i, 0, bgr.cols - 1)];
      acc += cv::Vec3f(p[0], p[1], p[2]) * wx[static_cast<std::size_t>(i)];
    }
    out += acc * wy[static_cast<std::size_t>(j)];
  }
  for (int k = 0; k < 3; ++k) {
    out[k] = std::clamp(out[k], 0.f, 255.f);
  }
  return out;
}

double viewWeight(double cos_angle, double distance_m, double border_px, const FrameView& view,
                  const TextureOptions& options) {
  if (cos_angle < view.cos_max_angle || distance_m >= options.max_distance_m || border_px <= 0) {
    return 0.0;
  }
  const double q = distance_m / options.max_distance_m;
  const double falloff = (1 - q * q) * (1 - q * q);
  double feather = 1.0;
  if (view.feather_px > 0 && border_px < view.feather_px) {
    const double x = border_px / view.feather_px;
    feather = x * x * (3 - 2 * x);
  }
  const double angle_term =
      options.angle_power == 2.0 ? cos_angle * cos_angle : std::pow(cos_angle, options.angle_power);
  return angle_term * falloff * feather * view.frame_weight;
}

double sampleView(const Eigen::Vector3d& c, const Eigen::Vector3d& n_cam, std::int32_t owner,
                  const FrameView& view, const TextureOptions& options, cv::Vec3f& colour) {
  if (c.z() <= kNearPlaneM) {
    return 0.0;
  }
  const double d = c.norm();
  if (d >= options.max_distance_m) {
    return 0.0;
  }
  const double cos_angle = n_cam.isZero() ? 1.0 : std::abs(n_cam.dot(c)) / d;
  const auto px = view.frame->projectCamera(c);
  if (!px) {
    return 0.0;
  }

  const double w_img = view.frame->width - 1, h_img = view.frame->height - 1;
  const double border =
      std::min({px->x(), px->y(), w_img - px->x(), h_img - px->y()}) + 0.5;  // > 0 inside
  double w = viewWeight(cos_angle, d, border, view, options);
  if (w <= 0 || px->x() < 0 || px->y() < 0 || px->x() > w_img || px->y() > h_img) {
    return 0.0;
  }
  if (view.depth != nullptr && view.depth->hidden(c, owner, options.occlusion_margin_m)) {
    return 0.0;
  }
  colour = (view.bicubic ? sampleBicubic(*view.image, px->x(), px->y())
                         : sampleBilinear(*view.image, px->x(), px->y())) *
           view.gain;
  return w;
}

}  // namespace pmap::texture
