#include "options_loader.h"

#include <cmath>

#include "pmap/common/error.h"

namespace pmap::sim::detail {
namespace {

void readLaser(JsonReader r, LaserOptions& laser) {
  laser.label = r.string("label", laser.label);
  laser.beams = r.integer("beams", laser.beams, 2, 100000);
  laser.aperture_deg = r.number("aperture_deg", laser.aperture_deg, positive(360.0));
  laser.max_range_m = r.number("max_range_m", laser.max_range_m, positive(1000.0));
  laser.position_m = r.triple("position_m", laser.position_m);
  laser.ypr_deg = r.triple("ypr_deg", laser.ypr_deg);
  laser.time_offset_s = r.number("time_offset_s", laser.time_offset_s, closed(0.0, 10.0));
  r.finish();
}

CameraMount readMount(JsonReader r) {
  CameraMount m;
  m.label = r.string("label", "");
  if (m.label.empty()) {
    r.failMissing("label");
  }
  m.position_m = r.triple("position_m", m.position_m);
  m.look = r.choice("look", "", {"left", "right", "forward", "backward"}, true);
  r.finish();
  return m;
}

void readLens(JsonReader r, CameraLensOptions& lens) {
  lens.vignetting = r.number("vignetting", lens.vignetting, closed(0.0, 0.9));
  lens.distortion = r.quintuple("distortion", lens.distortion, closed(-10.0, 10.0));
  if (std::abs(lens.distortion[2]) > 0.1 || std::abs(lens.distortion[3]) > 0.1) {
    r.fail("distortion",
           "the tangential coefficients p1, p2 (elements 2, 3) must be in [-0.1, 0.1]");
  }
  r.finish();
}

void readBlur(JsonReader r, CameraBlurOptions& blur) {
  blur.psf_sigma_px = r.interval("psf_sigma_px", blur.psf_sigma_px, closed(0.0, 10.0));
  blur.blurred_fraction = r.number("blurred_fraction", blur.blurred_fraction, closed(0.0, 1.0));
  blur.defocus_sigma_px = r.interval("defocus_sigma_px", blur.defocus_sigma_px, closed(0.0, 20.0));
  blur.motion_share = r.number("motion_share", blur.motion_share, closed(0.0, 1.0));
  blur.motion_length_px = r.interval("motion_length_px", blur.motion_length_px, closed(0.0, 100.0));
  r.finish();
}

void readExposure(JsonReader r, CameraExposureOptions& exposure) {
  exposure.gain = r.interval("gain", exposure.gain, positive(10.0));
  exposure.offset_dn = r.interval("offset_dn", exposure.offset_dn, closed(-100.0, 100.0));
  exposure.gamma = r.interval("gamma", exposure.gamma, closed(0.2, 5.0));
  r.finish();
}

void readCameraNoise(JsonReader r, CameraNoiseOptions& noise) {
  noise.read_sigma_dn = r.number("read_sigma_dn", noise.read_sigma_dn, closed(0.0, 50.0));
  noise.full_well_e = r.number("full_well_e", noise.full_well_e, closed(100.0, 1.0e7));
  r.finish();
}

void readCameras(JsonReader r, CameraOptions& cams) {
  cams.enabled = r.boolean("enabled", cams.enabled);
  cams.rate_hz = r.number("rate_hz", cams.rate_hz, positive(100.0));
  cams.time_offset_s = r.number("time_offset_s", cams.time_offset_s, closed(0.0, 10.0));
  cams.width_px = r.integer("width_px", cams.width_px, 16, 8192);
  cams.height_px = r.integer("height_px", cams.height_px, 16, 8192);
  cams.hfov_deg = r.number("hfov_deg", cams.hfov_deg, closed(10.0, 170.0));
  cams.jpeg_quality = r.integer("jpeg_quality", cams.jpeg_quality, 1, 100);
  if (r.has("mounts")) {
    cams.mounts.clear();
    for (JsonReader m : r.objects("mounts")) {
      cams.mounts.push_back(readMount(m));
    }
  }
  readLens(r.object("lens"), cams.lens);
  readBlur(r.object("blur"), cams.blur);
  readExposure(r.object("exposure"), cams.exposure);
  readCameraNoise(r.object("noise"), cams.noise);
  r.finish();
}

}  // namespace

PathSpec readPath(JsonReader r) {
  PathSpec p;
  p.waypoints = r.points2("waypoints", 2);
  p.speed_m_s = r.number("speed_m_s", p.speed_m_s, positive(10.0));
  p.corner_radius_m = r.number("corner_radius_m", p.corner_radius_m, closed(0.0, 100.0));
  p.max_yaw_rate_deg_s = r.number("max_yaw_rate_deg_s", p.max_yaw_rate_deg_s, positive(360.0));
  p.robot_radius_m = r.number("robot_radius_m", p.robot_radius_m, closed(0.0, 2.0));
  r.finish();
  std::string why;
  if (!p.validate(&why)) {
    throw ConfigError(r.file() + ": " + r.path() + ": " + why);
  }
  return p;
}

SensorOptions readSensors(JsonReader r) {
  SensorOptions s;
  s.cycle_hz = r.number("cycle_hz", s.cycle_hz, positive(1000.0));
  s.start_time_s = r.number("start_time_s", s.start_time_s, Range{0.0, 4.0e9, false, true});
  s.odometry_label = r.string("odometry_label", s.odometry_label);
  readLaser(r.object("laser_h"), s.laser_h);
  readLaser(r.object("laser_v"), s.laser_v);
  readCameras(r.object("cameras"), s.cameras);
  r.finish();
  std::string why;
  if (!s.validate(&why)) {
    throw ConfigError(r.file() + ": sensors: " + why);
  }
  return s;
}

NoiseOptions readNoise(JsonReader r) {
  NoiseOptions n;
  n.range_sigma_m = r.number("range_sigma_m", n.range_sigma_m, closed(0.0, 1.0));
  n.odometry_scale_error =
      r.number("odometry_scale_error", n.odometry_scale_error, closed(-0.5, 0.5));
  n.odometry_heading_drift_deg_per_m = r.number(
      "odometry_heading_drift_deg_per_m", n.odometry_heading_drift_deg_per_m, closed(-90.0, 90.0));
  n.odometry_random_signs = r.boolean("odometry_random_signs", n.odometry_random_signs);
  n.odometry_sigma_xy_m = r.number("odometry_sigma_xy_m", n.odometry_sigma_xy_m, closed(0.0, 1.0));
  n.odometry_sigma_yaw_deg =
      r.number("odometry_sigma_yaw_deg", n.odometry_sigma_yaw_deg, closed(0.0, 45.0));
  LaserErrorOptions& l = n.laser;
  l.sigma_per_m = r.number("range_sigma_per_m", l.sigma_per_m, closed(0.0, 0.1));
  l.incidence_factor = r.number("incidence_noise_factor", l.incidence_factor, closed(0.0, 10.0));
  l.grazing_dropout_deg =
      r.number("grazing_dropout_deg", l.grazing_dropout_deg, closed(0.001, 90.0));
  l.dropout_probability = r.number("dropout_probability", l.dropout_probability, closed(0.0, 1.0));
  l.spurious_probability =
      r.number("spurious_probability", l.spurious_probability, closed(0.0, 1.0));
  l.mixed_pixel_probability =
      r.number("mixed_pixel_probability", l.mixed_pixel_probability, closed(0.0, 1.0));
  l.mixed_pixel_jump_m = r.number("mixed_pixel_jump_m", l.mixed_pixel_jump_m, closed(0.001, 100.0));
  l.glass_return_deg = r.number("glass_return_deg", l.glass_return_deg, closed(0.0, 90.0));
  l.glass_dropout_probability =
      r.number("glass_dropout_probability", l.glass_dropout_probability, closed(0.0, 1.0));
  if (r.has("image_sigma")) {
    r.fail("image_sigma",
           "moved: image noise is sensors.cameras.noise (read_sigma_dn, full_well_e)");
  }
  r.finish();
  std::string why;
  if (!n.validate(&why)) {
    throw ConfigError(r.file() + ": noise: " + why);
  }
  return n;
}

}  // namespace pmap::sim::detail
