#include "pmap/texture/view_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace pmap::texture {
namespace {

// Keeps the part of `poly` with n . p >= d (one Sutherland-Hodgman step).
std::vector<Eigen::Vector3d> clipPlane(const std::vector<Eigen::Vector3d>& poly,
                                       const Eigen::Vector3d& n, double d) {
  std::vector<Eigen::Vector3d> out;
  const std::size_t m = poly.size();
  for (std::size_t i = 0; i < m; ++i) {
    const Eigen::Vector3d& a = poly[i];
    const Eigen::Vector3d& b = poly[(i + 1) % m];
    const double da = n.dot(a) - d;
    const double db = n.dot(b) - d;
    if (da >= 0) {
      out.push_back(a);
    }
    if ((da >= 0) != (db >= 0)) {
      out.push_back(a + (da / (da - db)) * (b - a));
    }
  }
  return out;
}

}  // namespace

std::vector<Eigen::Vector3d> clipToView(const std::vector<Eigen::Vector3d>& poly,
                                        const CameraFrame& frame, double margin_px) {
  std::vector<Eigen::Vector3d> cam;
  cam.reserve(poly.size());
  for (const Eigen::Vector3d& p : poly) {
    cam.push_back(frame.world_to_camera * p);
  }
  cam = clipPlane(cam, Eigen::Vector3d::UnitZ(), kNearPlaneM);
  // Rays through the (enlarged) image corners, pinhole model.
  const double fx = frame.K(0, 0), fy = frame.K(1, 1), cx = frame.K(0, 2), cy = frame.K(1, 2);
  const double x0 = (-0.5 - margin_px - cx) / fx, x1 = (frame.width - 0.5 + margin_px - cx) / fx;
  const double y0 = (-0.5 - margin_px - cy) / fy, y1 = (frame.height - 0.5 + margin_px - cy) / fy;
  const std::array<Eigen::Vector3d, 4> corner = {
      Eigen::Vector3d(x0, y0, 1), Eigen::Vector3d(x1, y0, 1), Eigen::Vector3d(x1, y1, 1),
      Eigen::Vector3d(x0, y1, 1)};
  const Eigen::Vector3d inside(0.5 * (x0 + x1), 0.5 * (y0 + y1), 1);
  for (std::size_t k = 0; k < 4 && !cam.empty(); ++k) {
    Eigen::Vector3d n = corner[k].cross(corner[(k + 1) % 4]);
    if (n.dot(inside) < 0) {
      n = -n;
    }
    cam = clipPlane(cam, n, 0.0);
  }
  return cam;
}

TexelBox visibleTexels(const TextureTile& tile, const CameraFrame& frame, double max_distance_m) {
  TexelBox box;
  // Distortion can move pixels a little outside the pinhole pyramid: margin.
  const double margin_px = 0.05 * std::max(frame.width, frame.height);
  const std::vector<Eigen::Vector3d> seen =
      clipToView({tile.origin, tile.origin + tile.length_u * tile.u,
                  tile.origin + tile.length_u * tile.u + tile.length_v * tile.v,
                  tile.origin + tile.length_v * tile.v},
                 frame, margin_px);
  if (seen.size() < 3) {
    return box;
  }
  // Footprint in tile coordinates (m), limited to the distance disc.
  const Eigen::Isometry3d camera_to_world = frame.world_to_camera.inverse();
  double s0 = tile.length_u, s1 = 0, t0 = tile.length_v, t1 = 0;
  for (const Eigen::Vector3d& c : seen) {
    const Eigen::Vector3d d = camera_to_world * c - tile.origin;
    s0 = std::min(s0, d.dot(tile.u));
    s1 = std::max(s1, d.dot(tile.u));
    t0 = std::min(t0, d.dot(tile.v));
    t1 = std::max(t1, d.dot(tile.v));
  }
  const Eigen::Vector3d rel = frame.centre - tile.origin;
  const double h = rel.dot(tile.normal);
  if (std::abs(h) >= max_distance_m) {
    return box;
  }
  const double r = std::sqrt(max_distance_m * max_distance_m - h * h);
  s0 = std::max(s0, rel.dot(tile.u) - r);
  s1 = std::min(s1, rel.dot(tile.u) + r);
  t0 = std::max(t0, rel.dot(tile.v) - r);
  t1 = std::min(t1, rel.dot(tile.v) + r);
  const double ppu = tile.width / tile.length_u;
  const double ppv = tile.height / tile.length_v;
  box.col0 = std::max(0, static_cast<int>(std::floor(s0 * ppu)));
  box.col1 = std::min(tile.width - 1, static_cast<int>(std::floor(s1 * ppu)));
  // Row 0 is the t = length_v edge.
  box.row0 = std::max(0, static_cast<int>(std::floor((tile.length_v - t1) * ppv)));
  box.row1 = std::min(tile.height - 1, static_cast<int>(std::floor((tile.length_v - t0) * ppv)));
  return box;
}

}  // namespace pmap::texture
