// [Texture]: how rectangles are textured from the camera images (doc/textures.md).
#pragma once

#include <string>

namespace pmap::texture {

struct TextureOptions {
  bool enabled = true;          ///< false: untextured map
  double pixels_per_m = 200.0;  ///< texture resolution (px/m), > 0
  /// Largest texture side (px): longer surfaces are cut into tiles (WebGL
  /// guarantees 4096).
  int max_side_px = 2048;
  /// All textures together stay below this (megapixels); the resolution is
  /// lowered uniformly beyond it.
  double max_total_mpx = 64.0;
  /// Memory for the blending accumulators (MB, 16 bytes per texel): tiles are
  /// processed in groups that fit, reading the images once per group.
  double memory_budget_mb = 512.0;
  /// How views are combined: "weighted" blends every good view (weights below);
  /// "best" keeps, per texel, the single best-weighted view (the paper pasted
  /// single stripes; kept for comparison).
  std::string blend = "weighted";
  /// How a view is sampled at a texel's projection: "bicubic" (Keys' cubic
  /// convolution, a = -0.5: keeps more of the fine detail that bilinear
  /// interpolation smooths away) or "bilinear".
  std::string interpolation = "bicubic";
  double max_view_angle_deg = 75.0;  ///< views more oblique than this are not used
  double max_distance_m = 6.0;       ///< views farther than this are not used
  double angle_power = 2.0;          ///< weight *= cos(angle)^power
  double feather_px = 60.0;          ///< weight ramps up from 0 at the image border (hides seams)
  /// weight *= clamp(slope, 0.05, 2)^power, slope = how much of the fine
  /// detail the frame keeps (detail_transfer.h); 0: no detail weighting (and
  /// one pass less over the images).
  double sharpness_power = 4.0;
  bool exposure_compensation = true;  ///< per-frame gain matched to the other views
  double occlusion_margin_m = 0.05;  ///< a texel farther than the nearest surface by this is hidden
  int threads = 1;                   ///< >= 1; the textures do not depend on it

  bool validate(std::string* why) const;
};

}  // namespace pmap::texture
