#include "pmap/refine/refine_options.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pmap::refine {
namespace {

TEST(RefineOptions, DefaultsAreValid) {
  std::string why;
  EXPECT_TRUE(RefineOptions{}.validate(&why)) << why;
}

TEST(RefineOptions, EachRuleNamesItsKey) {
  struct Case {
    void (*mutate)(RefineOptions&);
    const char* key;
  };
  const Case cases[] = {
      {[](RefineOptions& o) { o.fuse_sigmas = 0; }, "fuse_sigmas"},
      {[](RefineOptions& o) { o.seam_distance_m = -1; }, "seam_distance_m"},
      {[](RefineOptions& o) { o.seam_min_length_m = -0.1; }, "seam_min_length_m"},
      {[](RefineOptions& o) { o.seam_min_angle_deg = 90; }, "seam_min_angle_deg"},
      {[](RefineOptions& o) { o.seam_max_edge_angle_deg = 0; }, "seam_max_edge_angle_deg"},
      {[](RefineOptions& o) { o.seam_sigma_m = NAN; }, "seam_sigma_m"},
      {[](RefineOptions& o) { o.seam_give_up_m = 0; }, "seam_give_up_m"},
      {[](RefineOptions& o) { o.extent_sigma_m = 0; }, "extent_sigma_m"},
      {[](RefineOptions& o) { o.rotation_sigma_deg = INFINITY; }, "rotation_sigma_deg"},
      {[](RefineOptions& o) { o.robust_loss_sigmas = 0; }, "robust_loss_sigmas"},
      {[](RefineOptions& o) { o.max_points_per_surface = 9; }, "max_points_per_surface"},
      {[](RefineOptions& o) { o.max_iterations = 0; }, "max_iterations"},
      {[](RefineOptions& o) { o.manhattan_tolerance_deg = 45; }, "manhattan_tolerance_deg"},
      {[](RefineOptions& o) { o.manhattan_sigma_deg = 0; }, "manhattan_sigma_deg"},
      {[](RefineOptions& o) { o.max_normal_change_deg = 0; }, "max_normal_change_deg"},
  };
  for (const Case& c : cases) {
    RefineOptions o;
    c.mutate(o);
    std::string why;
    EXPECT_FALSE(o.validate(&why)) << c.key;
    EXPECT_NE(why.find(c.key), std::string::npos) << why;
  }
}

}  // namespace
}  // namespace pmap::refine
