#include "pmap/em/planar_em_options.h"

#include <gtest/gtest.h>

#include <functional>
#include <limits>

namespace pmap::em {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

struct BadValue {
  const char* name;  ///< must appear in the message
  std::function<void(PlanarEmOptions&)> set;
};

TEST(PlanarEmOptions, DefaultsValidate) {
  std::string why = "untouched";
  EXPECT_TRUE(PlanarEmOptions{}.validate(&why));
  EXPECT_EQ(why, "untouched");
  EXPECT_TRUE(PlanarEmOptions{}.validate(nullptr));
}

TEST(PlanarEmOptions, EachBadValueIsRejectedWithItsName) {
  const std::vector<BadValue> bad = {
      {"sigma_m", [](auto& o) { o.sigma_m = 0.0; }},
      {"sigma_m", [](auto& o) { o.sigma_m = -0.01; }},
      {"sigma_m", [](auto& o) { o.sigma_m = kNan; }},
      {"sigma_m", [](auto& o) { o.sigma_m = kInf; }},
      {"z_max_m", [](auto& o) { o.z_max_m = kNan; }},
      {"z_max_m", [](auto& o) { o.z_max_m = -1.0; }},
      {"z_max_m", [](auto& o) { o.z_max_m = 3.0 * o.sigma_m; }},
      {"kappa", [](auto& o) { o.kappa = -1.0; }},
      {"kappa", [](auto& o) { o.kappa = kNan; }},
      {"kappa", [](auto& o) { o.kappa = kInf; }},
      {"selection_interval", [](auto& o) { o.selection_interval = 0; }},
      {"max_new_per_round", [](auto& o) { o.max_new_per_round = 0; }},
      {"seed_outlier_probability", [](auto& o) { o.seed_outlier_probability = 0.0; }},
      {"seed_outlier_probability", [](auto& o) { o.seed_outlier_probability = 1.0; }},
      {"seed_outlier_probability", [](auto& o) { o.seed_outlier_probability = kNan; }},
      {"min_support", [](auto& o) { o.min_support = 2; }},
      {"min_rows", [](auto& o) { o.min_rows = 0; }},
      {"min_gain", [](auto& o) { o.min_gain = -0.5; }},
      {"min_gain", [](auto& o) { o.min_gain = kNan; }},
      {"min_curvature_radius_m", [](auto& o) { o.min_curvature_radius_m = 0.0; }},
      {"min_curvature_radius_m", [](auto& o) { o.min_curvature_radius_m = kNan; }},
      {"fuse_angle_deg", [](auto& o) { o.fuse_angle_deg = 0.0; }},
      {"fuse_angle_deg", [](auto& o) { o.fuse_angle_deg = 90.0; }},
      {"fuse_angle_deg", [](auto& o) { o.fuse_angle_deg = kNan; }},
      {"fuse_offset_m", [](auto& o) { o.fuse_offset_m = 0.0; }},
      {"fuse_gap_m", [](auto& o) { o.fuse_gap_m = -0.1; }},
      {"fuse_gap_m", [](auto& o) { o.fuse_gap_m = kNan; }},
      {"split_cell_m", [](auto& o) { o.split_cell_m = -1.0; }},
      {"split_min_offset_m", [](auto& o) { o.split_min_offset_m = 0.0; }},
      {"split_min_offset_m", [](auto& o) { o.split_min_offset_m = kNan; }},
      {"empty_area_cost", [](auto& o) { o.empty_area_cost = -1.0; }},
      {"empty_area_cost", [](auto& o) { o.empty_area_cost = kNan; }},
      {"max_iterations", [](auto& o) { o.max_iterations = 0; }},
      {"convergence_tolerance", [](auto& o) { o.convergence_tolerance = 0.0; }},
      {"convergence_tolerance", [](auto& o) { o.convergence_tolerance = kNan; }},
      {"convergence_patience", [](auto& o) { o.convergence_patience = 0; }},
      {"convergence_absolute_nats", [](auto& o) { o.convergence_absolute_nats = -1.0; }},
      {"convergence_absolute_nats", [](auto& o) { o.convergence_absolute_nats = kNan; }},
      {"responsibility_tolerance", [](auto& o) { o.responsibility_tolerance = 0.0; }},
      {"responsibility_tolerance", [](auto& o) { o.responsibility_tolerance = 0.1; }},
      {"responsibility_tolerance", [](auto& o) { o.responsibility_tolerance = kNan; }},
      {"fine_max_edge_m", [](auto& o) { o.fine_max_edge_m = 0.0; }},
      {"fine_max_edge_m", [](auto& o) { o.fine_max_edge_m = kInf; }},
      {"fine_cell_m", [](auto& o) { o.fine_cell_m = -0.01; }},
      {"fine_cell_m", [](auto& o) { o.fine_cell_m = 0.15; }},  // not below fine_max_edge_m
      {"fine_cell_m", [](auto& o) { o.fine_cell_m = kNan; }},
      {"min_curvature_depth_m", [](auto& o) { o.min_curvature_depth_m = -0.01; }},
      {"coarse_points", [](auto& o) { o.coarse_points = 500; }},
      {"coarse_points", [](auto& o) { o.coarse_points = -1; }},
      {"fine_iterations", [](auto& o) { o.fine_iterations = 0; }},
      {"block_points", [](auto& o) { o.block_points = 9999; }},
      {"block_points", [](auto& o) { o.block_points = -1; }},
      {"block_coarse_points", [](auto& o) { o.block_coarse_points = 500; }},
      {"block_margin_m", [](auto& o) { o.block_margin_m = -0.1; }},
      {"block_margin_m", [](auto& o) { o.block_margin_m = kNan; }},
      {"threads", [](auto& o) { o.threads = 0; }},
      {"threads", [](auto& o) { o.threads = 257; }},
  };
  for (const BadValue& b : bad) {
    PlanarEmOptions o;
    b.set(o);
    std::string why;
    EXPECT_FALSE(o.validate(&why)) << b.name;
    EXPECT_NE(why.find(b.name), std::string::npos) << "'" << why << "' does not name " << b.name;
    EXPECT_FALSE(o.validate(nullptr)) << b.name;
  }
}

TEST(PlanarEmOptions, BoundaryValuesThatAreAllowed) {
  PlanarEmOptions o;
  o.kappa = 0.0;
  o.min_gain = 0.0;
  o.fuse_gap_m = 0.0;
  o.empty_area_cost = 0.0;
  o.convergence_absolute_nats = 0.0;
  o.min_support = 3;
  o.min_rows = 1;
  o.threads = 256;
  o.max_iterations = 1;
  o.bounded = false;
  o.model_selection = false;
  o.selection_scoring = PlanarEmOptions::Scoring::kSoft;
  std::string why;
  EXPECT_TRUE(o.validate(&why)) << why;
}

}  // namespace
}  // namespace pmap::em
