#include "pmap/texture/texture_options.h"

#include <cmath>

namespace pmap::texture {

bool TextureOptions::validate(std::string* why) const {
  auto fail = [why](const char* rule) {
    if (why != nullptr) {
      *why = rule;
    }
    return false;
  };
  if (!(std::isfinite(pixels_per_m) && pixels_per_m > 0.0 && pixels_per_m <= 2000.0)) {
    return fail("pixels_per_m must be in (0, 2000]");
  }
  if (max_side_px < 16 || max_side_px > 16384)
    return fail("max_side_px must be in [16, 16384]");
  if (!(max_total_mpx >= 0.01 && max_total_mpx <= 1024)) {
    return fail("max_total_mpx must be in [0.01, 1024]");
  }
  if (!(memory_budget_mb >= 16 && memory_budget_mb <= 65536)) {
    return fail("memory_budget_mb must be in [16, 65536]");
  }
  if (threads < 1 || threads > 256)
    return fail("threads must be in [1, 256]");

  if (blend != "weighted" && blend != "best")
    return fail("blend must be 'weighted' or 'best'");
  if (interpolation != "bicubic" && interpolation != "bilinear")
    return fail("interpolation must be 'bicubic' or 'bilinear'");
  if (!(max_view_angle_deg > 0.0 && max_view_angle_deg < 90.0)) {
    return fail("max_view_angle_deg must be in (0, 90)");
  }
  if (!(std::isfinite(max_distance_m) && max_distance_m > 0.0)) {
    return fail("max_distance_m must be > 0");
  }
  if (!(std::isfinite(angle_power) && angle_power >= 0.0) ||
      !(std::isfinite(sharpness_power) && sharpness_power >= 0.0)) {
    return fail("angle_power and sharpness_power must be >= 0");
  }
  if (!(std::isfinite(feather_px) && feather_px >= 0.0))
    return fail("feather_px must be >= 0");
  if (!(std::isfinite(occlusion_margin_m) && occlusion_margin_m >= 0.0)) {
    return fail("occlusion_margin_m must be >= 0");
  }
  return true;
}

}  // namespace pmap::texture
