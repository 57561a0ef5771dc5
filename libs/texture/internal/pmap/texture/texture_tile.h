// A texture tile: a rectangle of the map (or a piece of one) with its texel
// grid. Long surfaces are cut into tiles no longer than max_side_px so that
// every texture fits viewers' texture limits (WebGL guarantees 4096).
//
// Texel (col, row) of a W x H tile has its centre at
//   origin + s * length_u * u + t * length_v * v,
//   s = (col + 0.5) / W,  t = (H - row - 0.5) / H,
// the convention of products/map_model.h (row 0 is the t = 1 edge).
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "pmap/products/map_model.h"
#include "pmap/texture/texture_options.h"

namespace pmap::texture {

struct TextureTile {
  std::int32_t surface_id = -1;
  std::int32_t tile = 0;  ///< index among the tiles of its surface

  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< corner c0 (world, m)
  Eigen::Vector3d u = Eigen::Vector3d::UnitX();      ///< unit, c0 -> c1
  Eigen::Vector3d v = Eigen::Vector3d::UnitY();      ///< unit, c0 -> c3
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double length_u = 0;  ///< m
  double length_v = 0;  ///< m
  int width = 0;        ///< texels along u
  int height = 0;       ///< texels along v

  /// World position of the centre of texel (col, row).
  Eigen::Vector3d texelCentre(double col, double row) const {
    const double s = (col + 0.5) / width;
    const double t = (height - row - 0.5) / height;
    return origin + (s * length_u) * u + (t * length_v) * v;
  }
  /// The tile as a quad of the map model (no texture yet).
  products::TexturedQuad quad() const;
};

/// Cuts every quad into tiles of at most `max_side_px` texels a side at
/// `pixels_per_m` (a quad is cut along its longer side; quads too thin for
/// one texel get one). The resolution is lowered uniformly when the total
/// would exceed `max_total_mpx`.
std::vector<TextureTile> planTiles(const std::vector<products::TexturedQuad>& quads,
                                   const TextureOptions& options);

}  // namespace pmap::texture
