#include "pmap/sim/sensor_options.h"

#include <cmath>

#include "pmap/sim/camera_model.h"
#include "pmap/sim/lens_distortion.h"

namespace pmap::sim {
namespace {

bool fail(std::string* why, const std::string& message) {
  if (why != nullptr) {
    *why = message;
  }
  return false;
}

bool allFinite(const std::array<double, 3>& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

}  // namespace

bool LaserOptions::validate(std::string* why) const {
  if (label.empty()) {
    return fail(why, "label must not be empty");
  }
  if (beams < 2 || beams > 100000) {
    return fail(why, "beams must be in [2, 100000]");
  }
  if (!(aperture_deg > 0.0 && aperture_deg <= 360.0)) {
    return fail(why, "aperture_deg must be in (0, 360]");
  }
  if (!(max_range_m > 0.0 && max_range_m <= 1000.0)) {
    return fail(why, "max_range_m must be in (0, 1000]");
  }
  if (!allFinite(position_m) || !allFinite(ypr_deg)) {
    return fail(why, "position_m and ypr_deg must be finite");
  }
  if (!(time_offset_s >= 0.0 && time_offset_s < 10.0)) {
    return fail(why, "time_offset_s must be in [0, 10)");
  }
  return true;
}

bool CameraOptions::validate(std::string* why) const {
  if (!(rate_hz > 0.0 && rate_hz <= 100.0)) {
    return fail(why, "rate_hz must be in (0, 100]");
  }
  if (!(time_offset_s >= 0.0 && time_offset_s < 10.0)) {
    return fail(why, "time_offset_s must be in [0, 10)");
  }
  if (width_px < 16 || width_px > 8192 || height_px < 16 || height_px > 8192) {
    return fail(why, "width_px and height_px must be in [16, 8192]");
  }
  if (!(hfov_deg >= 10.0 && hfov_deg <= 170.0)) {
    return fail(why, "hfov_deg must be in [10, 170]");
  }
  if (jpeg_quality < 1 || jpeg_quality > 100) {
    return fail(why, "jpeg_quality must be in [1, 100]");
  }
  for (const CameraMount& m : mounts) {
    if (m.label.empty() || !allFinite(m.position_m)) {
      return fail(why, "every mount needs a label and a finite position_m");
    }
    if (m.look != "left" && m.look != "right" && m.look != "forward" && m.look != "backward") {
      return fail(why, "look must be left, right, forward or backward");
    }
  }
  std::string inner;
  if (!lens.validate(&inner) || !blur.validate(&inner) || !exposure.validate(&inner) ||
      !noise.validate(&inner)) {
    return fail(why, inner);
  }
  const PinholeIntrinsics k =
      PinholeIntrinsics::fromFov(width_px, height_px, hfov_deg * M_PI / 180.0);
  return distortionIsUsable(k, lens.distortion, why);
}

SensorOptions::SensorOptions() {
  laser_h.label = "LASER_H";
  laser_h.position_m = {0.2, 0.0, 0.4};
  laser_v.label = "LASER_V";
  laser_v.position_m = {0.0, 0.0, 0.3};
  laser_v.ypr_deg = {0.0, -90.0, 0.0};
  laser_v.time_offset_s = 0.1;
  cameras.mounts = defaultCameraMounts();
}

bool SensorOptions::validate(std::string* why) const {
  if (!(cycle_hz > 0.0 && cycle_hz <= 1000.0)) {
    return fail(why, "cycle_hz must be in (0, 1000]");
  }
  if (!(std::isfinite(start_time_s) && start_time_s >= 0.0 && start_time_s < 4.0e9)) {
    return fail(why, "start_time_s must be in [0, 4e9)");
  }
  if (odometry_label.empty()) {
    return fail(why, "odometry label must not be empty");
  }
  std::string inner;
  if (!laser_h.validate(&inner)) {
    return fail(why, "laser_h: " + inner);
  }
  if (!laser_v.validate(&inner)) {
    return fail(why, "laser_v: " + inner);
  }
  if (!cameras.validate(&inner)) {
    return fail(why, "cameras: " + inner);
  }
  const double period_s = 1.0 / cycle_hz;
  if (laser_h.time_offset_s >= period_s || laser_v.time_offset_s >= period_s ||
      cameras.time_offset_s >= period_s) {
    return fail(why, "time offsets must be shorter than one cycle (1 / cycle_hz)");
  }
  if (cameras.rate_hz > cycle_hz) {
    return fail(why, "cameras.rate_hz must not exceed cycle_hz");
  }
  return true;
}

bool LaserErrorOptions::validate(std::string* why) const {
  if (!(sigma_per_m >= 0.0 && sigma_per_m <= 0.1)) {
    return fail(why, "range_sigma_per_m must be in [0, 0.1]");
  }
  if (!(incidence_factor >= 0.0 && incidence_factor <= 10.0)) {
    return fail(why, "incidence_noise_factor must be in [0, 10]");
  }
  if (!(grazing_dropout_deg > 0.0 && grazing_dropout_deg <= 90.0)) {
    return fail(why, "grazing_dropout_deg must be in (0, 90]");
  }
  for (const double p : {dropout_probability, spurious_probability, mixed_pixel_probability}) {
    if (!(p >= 0.0 && p <= 1.0)) {
      return fail(why,
                  "dropout_probability, spurious_probability and mixed_pixel_probability must be "
                  "in [0, 1]");
    }
  }
  if (!(mixed_pixel_jump_m > 0.0 && mixed_pixel_jump_m <= 100.0)) {
    return fail(why, "mixed_pixel_jump_m must be in (0, 100]");
  }
  if (!(glass_return_deg >= 0.0 && glass_return_deg <= 90.0)) {
    return fail(why, "glass_return_deg must be in [0, 90]");
  }
  if (!(glass_dropout_probability >= 0.0 && glass_dropout_probability <= 1.0)) {
    return fail(why, "glass_dropout_probability must be in [0, 1]");
  }
  return true;
}

bool NoiseOptions::validate(std::string* why) const {
  if (!(range_sigma_m >= 0.0 && range_sigma_m <= 1.0)) {
    return fail(why, "range_sigma_m must be in [0, 1]");
  }
  if (!laser.validate(why)) {
    return false;
  }
  if (!(std::abs(odometry_scale_error) <= 0.5)) {
    return fail(why, "odometry_scale_error must be in [-0.5, 0.5]");
  }
  if (!(std::abs(odometry_heading_drift_deg_per_m) <= 90.0)) {
    return fail(why, "odometry_heading_drift_deg_per_m must be in [-90, 90]");
  }
  if (!(odometry_sigma_xy_m >= 0.0 && odometry_sigma_xy_m <= 1.0) ||
      !(odometry_sigma_yaw_deg >= 0.0 && odometry_sigma_yaw_deg <= 45.0)) {
    return fail(why, "odometry white noise must be in [0, 1] m and [0, 45] deg");
  }
  return true;
}

std::vector<CameraMount> defaultCameraMounts() {
  return {CameraMount{"CAMERA_LEFT", {0.0, 0.05, 1.0}, "left"},
          CameraMount{"CAMERA_RIGHT", {0.0, -0.05, 1.0}, "right"}};
}

}  // namespace pmap::sim
