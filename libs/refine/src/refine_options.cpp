#include "pmap/refine/refine_options.h"

#include <cmath>

namespace pmap::refine {
namespace {

bool fail(std::string* why, const std::string& rule) {
  if (why != nullptr) {
    *why = rule;
  }
  return false;
}

bool positive(double v) {
  return std::isfinite(v) && v > 0.0;
}

bool inOpen(double v, double lo, double hi) {
  return std::isfinite(v) && v > lo && v < hi;
}

}  // namespace

bool RefineOptions::validate(std::string* why) const {
  if (!positive(fuse_sigmas))
    return fail(why, "fuse_sigmas must be > 0");
  if (!positive(seam_distance_m))
    return fail(why, "seam_distance_m must be > 0");
  if (!(std::isfinite(seam_min_length_m) && seam_min_length_m >= 0.0)) {
    return fail(why, "seam_min_length_m must be >= 0");
  }
  if (!inOpen(seam_min_angle_deg, 0.0, 90.0)) {
    return fail(why, "seam_min_angle_deg must be in (0, 90)");
  }
  if (!inOpen(seam_max_edge_angle_deg, 0.0, 90.0)) {
    return fail(why, "seam_max_edge_angle_deg must be in (0, 90)");
  }
  if (!positive(seam_sigma_m))
    return fail(why, "seam_sigma_m must be > 0");
  if (!positive(seam_give_up_m))
    return fail(why, "seam_give_up_m must be > 0");
  if (!positive(extent_sigma_m))
    return fail(why, "extent_sigma_m must be > 0");
  if (!positive(rotation_sigma_deg))
    return fail(why, "rotation_sigma_deg must be > 0");
  if (!positive(robust_loss_sigmas))
    return fail(why, "robust_loss_sigmas must be > 0");
  if (max_points_per_surface < 10)
    return fail(why, "max_points_per_surface must be >= 10");
  if (max_iterations < 1)
    return fail(why, "max_iterations must be >= 1");
  if (!inOpen(manhattan_tolerance_deg, 0.0, 45.0)) {
    return fail(why, "manhattan_tolerance_deg must be in (0, 45)");
  }
  if (!positive(manhattan_sigma_deg))
    return fail(why, "manhattan_sigma_deg must be > 0");
  if (!inOpen(opening_max_angle_deg, 0.0, 90.0)) {
    return fail(why, "opening_max_angle_deg must be in (0, 90)");
  }
  if (!positive(max_normal_change_deg))
    return fail(why, "max_normal_change_deg must be > 0");
  return true;
}

}  // namespace pmap::refine
