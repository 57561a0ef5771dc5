#include "pmap/sim/image_sensor.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

#include "pmap/sim/rng.h"

namespace pmap::sim {
namespace {

/// 8-bit output of every clipped raw value in [0, 255], sampled every 1/16 DN,
/// through the tone curve.
class ToneCurve {
 public:
  explicit ToneCurve(double gamma) : identity_(gamma == 1.0) {
    if (!identity_) {
      for (std::size_t i = 0; i < lut_.size(); ++i) {
        const double x = static_cast<double>(i) / kSteps / 255.0;
        lut_[i] = 255.0 * std::pow(x, 1.0 / gamma);
      }
    }
  }
  unsigned char operator()(double clipped) const {
    if (identity_) {
      return static_cast<unsigned char>(std::lround(clipped));
    }
    const double pos = clipped * kSteps;
    const auto i = std::min(static_cast<std::size_t>(pos), lut_.size() - 2);
    const double t = pos - static_cast<double>(i);
    return static_cast<unsigned char>(std::lround(lut_[i] + t * (lut_[i + 1] - lut_[i])));
  }

 private:
  static constexpr int kSteps = 16;
  bool identity_;
  std::array<double, 255 * kSteps + 2> lut_{};
};

}  // namespace

SensorReadout readSensor(const cv::Mat& irradiance, const cv::Mat& falloff,
                         const CameraNoiseOptions& noise, const FrameExposure& exposure,
                         std::uint64_t seed) {
  assert(irradiance.type() == CV_32FC3);
  assert(falloff.empty() || (falloff.type() == CV_32FC1 && falloff.size() == irradiance.size()));
  Rng rng(seed);
  const ToneCurve tone(exposure.gamma);
  const double read_var = noise.read_sigma_dn * noise.read_sigma_dn;
  const double shot_var_per_dn = 255.0 / noise.full_well_e;
  SensorReadout out;
  out.image.create(irradiance.rows, irradiance.cols, CV_8UC3);
  std::size_t saturated = 0;
  for (int v = 0; v < irradiance.rows; ++v) {
    const auto* in = irradiance.ptr<cv::Vec3f>(v);
    const float* w = falloff.empty() ? nullptr : falloff.ptr<float>(v);
    auto* px = out.image.ptr<cv::Vec3b>(v);
    for (int u = 0; u < irradiance.cols; ++u) {
      const double scale = exposure.gain * (w != nullptr ? w[u] : 1.0);
      for (int ch = 0; ch < 3; ++ch) {
        const double signal = scale * in[u][ch];
        const double var = read_var + std::max(signal, 0.0) * shot_var_per_dn;
        const double raw =
            signal + exposure.offset_dn + (var > 0.0 ? std::sqrt(var) * rng.normal() : 0.0);
        saturated += raw >= 255.0 ? 1 : 0;
        px[u][ch] = tone(std::clamp(raw, 0.0, 255.0));
      }
    }
  }
  out.saturated_fraction =
      static_cast<double>(saturated) / (3.0 * irradiance.rows * std::max(1, irradiance.cols));
  return out;
}

}  // namespace pmap::sim
