// [Poses] plane_refine_*: the options of plane_poses.h (planes correct
// poses), apart so that the config loader does not need the point map.
#pragma once

#include <string>

namespace pmap::refine {

/// [Poses] plane_refine_* (doc/configuration.md).
struct PlanePoseOptions {
  bool enabled = false;                 ///< [Poses] plane_refinement (offline mode only)
  double knot_spacing_m = 1.0;          ///< a correction knot every so much path (m)
  double sigma_m = 0.02;                ///< point-to-plane noise (m)
  double motion_sigma_m_per_m = 0.01;   ///< relative motion between knots, per metre (m/m)
  double motion_sigma_deg_per_m = 0.1;  ///< ... heading (deg/m)
  double absolute_sigma_m = 0.03;       ///< each knot's correction: prior sigma (m), 0 = none
  double absolute_sigma_deg = 0.3;      ///< ... heading (deg)
  double max_normal_z = 0.2;            ///< vertical surfaces: |n_z| at most this
  int points_per_scan_surface = 8;      ///< points of one scan on one surface used, at most
  double huber_sigmas = 2.0;            ///< Huber threshold of (P2), in sigmas
  int rounds = 1;                       ///< fit, move the scans, re-run the EM: this many times
  int max_iterations = 50;              ///< Ceres iterations per round
  bool validate(std::string* why) const;
};

}  // namespace pmap::refine
