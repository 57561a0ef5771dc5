// Sensor and noise options of a simulated robot. Defaults are the paper's robot
// (see doc/simulator.md); every field can be overridden in a world file's
// "sensors" and "noise" blocks.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "pmap/sim/camera_imaging_options.h"

namespace pmap::sim {

/// A 2D laser scanner (MRPT CObservation2DRangeScan, rightToLeft = true).
struct LaserOptions {
  std::string label;
  int beams = 181;
  double aperture_deg = 180.0;                        ///< field of view, degrees
  double max_range_m = 30.0;                          ///< beams without a hit report this, invalid
  std::array<double, 3> position_m{{0.0, 0.0, 0.0}};  ///< on the robot, metres
  std::array<double, 3> ypr_deg{{0.0, 0.0, 0.0}};     ///< yaw, pitch, roll, degrees (CPose3D)
  double time_offset_s = 0.0;  ///< after the cycle's odometry timestamp, seconds
  bool validate(std::string* why) const;
};

/// Where a camera sits on the robot and which way it looks.
struct CameraMount {
  std::string label;
  std::array<double, 3> position_m{{0.0, 0.0, 1.0}};  ///< optical centre on the robot, metres
  std::string look = "left";  ///< "left", "right", "forward" or "backward" (optical axis)
};

/// Pinhole cameras rendering the textured world (MRPT CObservationImage), with
/// the lens, blur, exposure and noise of real cameras (camera_imaging_options.h).
struct CameraOptions {
  bool enabled = true;
  double rate_hz = 2.0;         ///< images per second per camera
  double time_offset_s = 0.05;  ///< after the cycle's odometry timestamp, seconds
  int width_px = 640;
  int height_px = 480;
  double hfov_deg = 90.0;  ///< horizontal field of view, degrees
  int jpeg_quality = 90;   ///< 1..100
  std::vector<CameraMount> mounts;
  CameraLensOptions lens;
  CameraBlurOptions blur;
  CameraExposureOptions exposure;
  CameraNoiseOptions noise;
  bool validate(std::string* why) const;
};

/// All sensors and the cycle timing.
struct SensorOptions {
  double cycle_hz = 5.0;               ///< odometry + laser cycles per second
  double start_time_s = 1767225600.0;  ///< UNIX time of cycle 0 (2026-01-01T00:00:00Z)
  std::string odometry_label = "ODOMETRY";
  LaserOptions laser_h;  ///< the pose (horizontal) laser
  LaserOptions laser_v;  ///< the structure (vertical) laser
  CameraOptions cameras;
  SensorOptions();
  bool validate(std::string* why) const;
};

/// What real lasers do beyond a constant Gaussian range noise (laser_sim.h),
/// both lasers. All off by default: the worlds of doc/RESULTS.md are drawn as
/// before, to the bit.
struct LaserErrorOptions {
  /// The range noise's standard deviation grows by this per metre of range
  /// (m/m): sigma(r) = range_sigma_m + sigma_per_m r.
  double sigma_per_m = 0.0;
  /// ... and with the angle of incidence a between the beam and the
  /// surface's normal: times 1 + incidence_factor (1 / cos a - 1), cos a
  /// floored at 0.1 (a spot stretched along a slanted surface).
  double incidence_factor = 0.0;
  /// Beams meeting a surface more than this far from its normal (deg)
  /// return nothing; 90: never.
  double grazing_dropout_deg = 90.0;
  /// Each return is lost with this probability (dark or absorbing
  /// surfaces), [0, 1].
  double dropout_probability = 0.0;
  /// Each beam returns, with this probability, a range drawn uniformly
  /// short of its hit (dust, a passer-by's leg, a reflection), [0, 1].
  double spurious_probability = 0.0;
  /// A beam whose neighbour hits another object (or nothing) more than
  /// mixed_pixel_jump_m nearer or further (a depth edge) returns, with this
  /// probability, a range between the two (a spot split between both
  /// surfaces), [0, 1].
  double mixed_pixel_probability = 0.0;
  double mixed_pixel_jump_m = 0.3;
  /// Glass (a rectangle of kind "glass"): a beam meeting a pane within
  /// this many degrees of its normal returns from the pane (the specular
  /// reflection), any other goes through it and returns from what lies
  /// behind, degrees in [0, 90].
  double glass_return_deg = 10.0;
  /// ... and a beam that went through glass is lost with this probability
  /// (the return too weak after two passes through the pane), [0, 1].
  double glass_dropout_probability = 0.0;
  bool validate(std::string* why) const;
};

/// Noise of the lasers and the odometry (image noise: CameraOptions::noise).
struct NoiseOptions {
  double range_sigma_m = 0.02;                    ///< Gaussian range noise, both lasers, metres
  LaserErrorOptions laser;                        ///< beyond the Gaussian (off by default)
  double odometry_scale_error = 0.02;             ///< systematic distance scale error (fraction)
  double odometry_heading_drift_deg_per_m = 1.0;  ///< systematic heading drift, degrees per metre
  bool odometry_random_signs = true;              ///< signs of the two drifts drawn from the seed
  double odometry_sigma_xy_m = 0.002;             ///< white noise per cycle, metres
  double odometry_sigma_yaw_deg = 0.05;           ///< white noise per cycle, degrees
  bool validate(std::string* why) const;
};

/// Default mounts: two cameras looking left and right at 1.0 m.
std::vector<CameraMount> defaultCameraMounts();

}  // namespace pmap::sim
