#include "pmap/em/planar_em_options.h"

#include <cmath>

namespace pmap::em {
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

}  // namespace

bool PlanarEmOptions::validate(std::string* why) const {
  if (!positive(sigma_m))
    return fail(why, "sigma_m must be > 0");
  if (!positive(z_max_m) || z_max_m <= 3.0 * sigma_m) {
    return fail(why, "z_max_m must be > 3 * sigma_m");
  }
  if (!(std::isfinite(kappa) && kappa >= 0.0))
    return fail(why, "kappa must be >= 0");
  if (selection_interval < 1)
    return fail(why, "selection_interval must be >= 1");
  if (max_new_per_round < 1)
    return fail(why, "max_new_per_round must be >= 1");
  if (!(seed_outlier_probability > 0.0 && seed_outlier_probability < 1.0)) {
    return fail(why, "seed_outlier_probability must be in (0, 1)");
  }
  if (min_support < 3)
    return fail(why, "min_support must be >= 3");
  if (min_rows < 1)
    return fail(why, "min_rows must be >= 1");
  if (!(std::isfinite(min_gain) && min_gain >= 0.0))
    return fail(why, "min_gain must be >= 0");
  if (!positive(min_curvature_radius_m))
    return fail(why, "min_curvature_radius_m must be > 0");
  if (!(fuse_angle_deg > 0.0 && fuse_angle_deg < 90.0)) {
    return fail(why, "fuse_angle_deg must be in (0, 90)");
  }
  if (!positive(fuse_offset_m) || !(std::isfinite(fuse_gap_m) && fuse_gap_m >= 0.0)) {
    return fail(why, "fuse_offset_m must be > 0 and fuse_gap_m >= 0");
  }
  if (!positive(split_cell_m) || !positive(split_min_offset_m)) {
    return fail(why, "split_cell_m and split_min_offset_m must be > 0");
  }
  if (!(std::isfinite(empty_area_cost) && empty_area_cost >= 0.0)) {
    return fail(why, "empty_area_cost must be >= 0");
  }
  if (max_iterations < 1)
    return fail(why, "max_iterations must be >= 1");
  if (!positive(convergence_tolerance))
    return fail(why, "convergence_tolerance must be > 0");
  if (convergence_patience < 1)
    return fail(why, "convergence_patience must be >= 1");
  if (!(std::isfinite(convergence_absolute_nats) && convergence_absolute_nats >= 0.0)) {
    return fail(why, "convergence_absolute_nats must be >= 0");
  }
  if (!(responsibility_tolerance > 0.0 && responsibility_tolerance < 0.1)) {
    return fail(why, "responsibility_tolerance must be in (0, 0.1)");
  }
  if (!positive(fine_max_edge_m))
    return fail(why, "fine_max_edge_m must be > 0");
  if (threads < 1 || threads > 256)
    return fail(why, "threads must be in [1, 256]");
  return true;
}

}  // namespace pmap::em
