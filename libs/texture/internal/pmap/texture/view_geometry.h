// What part of the map a camera frame can see: the frame's viewing pyramid
// (image borders, near plane) clipping world polygons, and the texel box of a
// tile that can project into the image.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "pmap/texture/camera_frame.h"
#include "pmap/texture/texture_tile.h"

namespace pmap::texture {

/// Near plane of every frame (m in front of the optical centre).
constexpr double kNearPlaneM = 0.02;

/// The part of the convex world polygon `poly` inside the frame's viewing
/// pyramid (pinhole, image enlarged by `margin_px` on every side), in the
/// camera frame (Sutherland-Hodgman against the five planes). Empty: unseen.
std::vector<Eigen::Vector3d> clipToView(const std::vector<Eigen::Vector3d>& poly,
                                        const CameraFrame& frame, double margin_px);

/// Inclusive texel range of a tile; empty when first > last.
struct TexelBox {
  int col0 = 0, col1 = -1, row0 = 0, row1 = -1;
  bool empty() const { return col1 < col0 || row1 < row0; }
  long long count() const { return empty() ? 0 : 1LL * (col1 - col0 + 1) * (row1 - row0 + 1); }
};

/// Texels of `tile` that may project into the frame within `max_distance_m`
/// of its optical centre (a superset: callers still project each texel).
TexelBox visibleTexels(const TextureTile& tile, const CameraFrame& frame, double max_distance_m);

}  // namespace pmap::texture
