#include "pmap/texture/texture_tile.h"

#include <algorithm>
#include <cmath>

namespace pmap::texture {

products::TexturedQuad TextureTile::quad() const {
  products::TexturedQuad q;
  q.surface_id = surface_id;
  q.tile = tile;
  q.corners = {origin, origin + length_u * u, origin + length_u * u + length_v * v,
               origin + length_v * v};
  q.normal = normal;
  return q;
}

namespace {

// Texels along a length, as a double: a quad kilometres long (bad poses)
// must not overflow an int here.
double texels(double length_m, double pixels_per_m) {
  return std::max(1.0, std::ceil(length_m * pixels_per_m - 1e-9));
}

// Tiles of one quad, at most: a longer quad (only absurd geometry makes one)
// gets a coarser texture instead of millions of tiles.
constexpr double kMaxTilesPerQuad = 4096.0;

// Cuts one quad into pieces along u and v of at most max_side texels.
void cutQuad(const products::TexturedQuad& q, double ppm, int max_side,
             std::vector<TextureTile>& out) {
  const Eigen::Vector3d eu = q.corners[1] - q.corners[0];
  const Eigen::Vector3d ev = q.corners[3] - q.corners[0];
  const double lu = eu.norm();
  const double lv = ev.norm();
  if (!(lu > 0) || !(lv > 0)) {
    return;
  }
  double tiles_u = std::ceil(texels(lu, ppm) / max_side);
  double tiles_v = std::ceil(texels(lv, ppm) / max_side);
  while (tiles_u * tiles_v > kMaxTilesPerQuad) {
    ppm *= 0.5;
    tiles_u = std::ceil(texels(lu, ppm) / max_side);
    tiles_v = std::ceil(texels(lv, ppm) / max_side);
  }
  const int nu = static_cast<int>(tiles_u);
  const int nv = static_cast<int>(tiles_v);
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      TextureTile t;
      t.surface_id = q.surface_id;
      t.tile = j * nu + i;

      t.u = eu / lu;
      t.v = ev / lv;
      t.normal = q.normal;
      t.length_u = lu / nu;
      t.length_v = lv / nv;
      t.origin = q.corners[0] + (i * t.length_u) * t.u + (j * t.length_v) * t.v;
      t.width = static_cast<int>(std::min<double>(max_side, texels(t.length_u, ppm)));
      t.height = static_cast<int>(std::min<double>(max_side, texels(t.length_v, ppm)));
      out.push_back(t);
    }
  }
}

}  // namespace

std::vector<TextureTile> planTiles(const std::vector<products::TexturedQuad>& quads,
                                   const TextureOptions& options) {
  double area = 0;
  for (const auto& q : quads) {
    area += (q.corners[1] - q.corners[0]).norm() * (q.corners[3] - q.corners[0]).norm();
  }
  double ppm = options.pixels_per_m;
  const double budget = options.max_total_mpx * 1e6;
  if (area * ppm * ppm > budget) {
    ppm = std::sqrt(budget / area);
  }
  std::vector<TextureTile> tiles;
  for (const auto& q : quads) {
    cutQuad(q, ppm, options.max_side_px, tiles);
  }
  return tiles;
}

}  // namespace pmap::texture
