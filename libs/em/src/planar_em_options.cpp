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
  if (auto_sigma_points < 100)
    return fail(why, "auto_sigma_points must be >= 100");
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
  if (!(std::isfinite(min_curvature_depth_m) && min_curvature_depth_m >= 0.0))
    return fail(why, "min_curvature_depth_m must be >= 0");
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
  if (!(fine_cell_m == 0.0 || (fine_cell_m > 0.0 && fine_cell_m < fine_max_edge_m)))
    return fail(why, "fine_cell_m must be 0 (off) or in (0, fine_max_edge_m)");
  if (coarse_points != 0 && coarse_points < 1000)
    return fail(why, "coarse_points must be 0 (off) or >= 1000");
  if (fine_iterations < 1)
    return fail(why, "fine_iterations must be >= 1");
  if (block_points != 0 && block_points < 10000)
    return fail(why, "block_points must be 0 (off) or >= 10000");
  if (block_coarse_points != 0 && block_coarse_points < 1000)
    return fail(why, "block_coarse_points must be 0 (off) or >= 1000");
  if (!(std::isfinite(block_margin_m) && block_margin_m >= 0.0))
    return fail(why, "block_margin_m must be >= 0");
  if (threads < 1 || threads > 256)
    return fail(why, "threads must be in [1, 256]");
  return rules.validate(why);
}

bool SelectionRules::validate(std::string* why) const {
  if (same_place_overlap_percent < 1 || same_place_overlap_percent > 100)
    return fail(why, "rules.same_place_overlap_percent must be in [1, 100]");
  if (!(std::isfinite(same_place_clearance) && same_place_clearance >= 1.0))
    return fail(why, "rules.same_place_clearance must be >= 1");
  if (!positive(grow_sigmas))
    return fail(why, "rules.grow_sigmas must be > 0");
  if (recut_min_growth_percent < 0 || recut_max_transfer_percent < 1 ||
      recut_max_transfer_percent > 100) {
    return fail(why,
                "rules.recut_min_growth_percent must be >= 0 and "
                "rules.recut_max_transfer_percent in [1, 100]");
  }
  if (removal_passes < 1 || tabu_rounds < 0)
    return fail(why, "rules.removal_passes must be >= 1 and rules.tabu_rounds >= 0");
  if (!(tabu_angle_deg >= 0.0 && tabu_angle_deg < 90.0) || !(tabu_offset_sigmas >= 0.0) ||
      !(tabu_centre_m >= 0.0) || !(tabu_centre_per_side >= 0.0)) {
    return fail(why, "rules.tabu_* must be >= 0 (angle below 90 degrees)");
  }
  if (!(poor_coverage_min_area_m2 >= 0.0) || poor_coverage_min_points < 1 ||
      !(poor_coverage_empty_fraction > 0.0 && poor_coverage_empty_fraction < 1.0)) {
    return fail(why, "rules.poor_coverage_*: area >= 0, points >= 1, fraction in (0, 1)");
  }
  if (min_part_points < 3 || !positive(sampled_cell_spacings))
    return fail(why, "rules.min_part_points must be >= 3 and rules.sampled_cell_spacings > 0");
  if (coherent_neighbours < 0 || coherent_neighbours > 4 ||
      !(curved_min_variance_explained >= 0.0 && curved_min_variance_explained <= 1.0)) {
    return fail(why,
                "rules.coherent_neighbours must be in [0, 4] and "
                "rules.curved_min_variance_explained in [0, 1]");
  }
  if (!positive(residual_cell_points) || residual_min_cell_points < 1 ||
      !positive(residual_sigmas)) {
    return fail(why, "rules.residual_*: cell points > 0, min cell points >= 1, sigmas > 0");
  }
  if (!positive(corner_end_window_m) || !(corner_min_leg_beyond_m >= 0.0) ||
      corner_on_plane_percent < 0 || corner_on_plane_percent > 100 || corner_beside_percent < 0 ||
      corner_beside_percent > 100 || !(corner_beside_margin_m >= 0.0)) {
    return fail(why, "rules.corner_*: lengths >= 0 (window > 0), percentages in [0, 100]");
  }
  if (seed_attempts_per_surface < 1)
    return fail(why, "rules.seed_attempts_per_surface must be >= 1");
  return true;
}

}  // namespace pmap::em
