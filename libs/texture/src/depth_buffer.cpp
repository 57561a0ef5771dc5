#include "pmap/texture/depth_buffer.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pmap/texture/view_geometry.h"

namespace pmap::texture {

DepthBuffer::DepthBuffer(const CameraFrame& frame, const std::vector<TextureTile>& tiles,
                         const products::ColoredTriangles& fine, int cell_px)
    : fx_(frame.K(0, 0)),
      fy_(frame.K(1, 1)),
      cx_(frame.K(0, 2)),
      cy_(frame.K(1, 2)),
      cell_px_(std::max(1, cell_px)),
      cols_((frame.width + cell_px_ - 1) / cell_px_),
      rows_((frame.height + cell_px_ - 1) / cell_px_),
      depth_(static_cast<std::size_t>(cols_) * static_cast<std::size_t>(rows_),
             std::numeric_limits<float>::infinity()),
      owner_(depth_.size(), kNothing) {
  for (const TextureTile& t : tiles) {
    renderTile(t, frame);
  }
  for (const auto& tri : fine.triangles) {
    renderTriangle({fine.vertices[tri[0]], fine.vertices[tri[1]], fine.vertices[tri[2]]}, frame);
  }
}

Eigen::Vector3d DepthBuffer::cellRay(int col, int row) const {
  const double u = (col + 0.5) * cell_px_ - 0.5;
  const double v = (row + 0.5) * cell_px_ - 0.5;
  return {(u - cx_) / fx_, (v - cy_) / fy_, 1.0};
}

bool DepthBuffer::cellBox(const std::vector<Eigen::Vector3d>& cam, int& c0, int& c1, int& r0,
                          int& r1) const {
  if (cam.size() < 3) {
    return false;
  }
  double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
  for (const Eigen::Vector3d& c : cam) {
    const double u = fx_ * c.x() / c.z() + cx_;
    const double v = fy_ * c.y() / c.z() + cy_;
    u0 = std::min(u0, u), u1 = std::max(u1, u), v0 = std::min(v0, v), v1 = std::max(v1, v);
  }
  auto cell = [this](double px) { return static_cast<int>(std::floor((px + 0.5) / cell_px_)); };
  c0 = std::max(0, cell(u0)), c1 = std::min(cols_ - 1, cell(u1));
  r0 = std::max(0, cell(v0)), r1 = std::min(rows_ - 1, cell(v1));
  return c0 <= c1 && r0 <= r1;
}

void DepthBuffer::write(int col, int row, double depth, std::int32_t owner) {
  const std::size_t i = index(col, row);
  if (depth < depth_[i]) {
    depth_[i] = static_cast<float>(depth);
    owner_[i] = owner;
  }
}

void DepthBuffer::renderTile(const TextureTile& tile, const CameraFrame& frame) {
  const auto corners = tile.quad().corners;
  const std::vector<Eigen::Vector3d> cam =
      clipToView(std::vector<Eigen::Vector3d>(corners.begin(), corners.end()), frame, 0.0);

  int c0, c1, r0, r1;
  if (!cellBox(cam, c0, c1, r0, r1)) {
    return;
  }
  const Eigen::Matrix3d R = frame.world_to_camera.linear();
  const Eigen::Vector3d o = frame.world_to_camera * tile.origin;
  const Eigen::Vector3d n = R * tile.normal, eu = R * tile.u, ev = R * tile.v;
  const double plane = n.dot(o);
  for (int row = r0; row <= r1; ++row) {
    for (int col = c0; col <= c1; ++col) {
      const Eigen::Vector3d ray = cellRay(col, row);
      const double denom = n.dot(ray);
      if (std::abs(denom) < 1e-12) {
        continue;
      }
      const double depth = plane / denom;  // ray has z = 1: lambda is the depth
      if (depth <= kNearPlaneM) {
        continue;
      }
      const Eigen::Vector3d d = depth * ray - o;
      const double s = d.dot(eu), t = d.dot(ev);
      if (s >= 0 && s <= tile.length_u && t >= 0 && t <= tile.length_v) {
        write(col, row, depth, tile.surface_id);
      }
    }
  }
}

void DepthBuffer::renderTriangle(const std::array<Eigen::Vector3d, 3>& world,
                                 const CameraFrame& frame) {
  const std::vector<Eigen::Vector3d> cam = clipToView({world[0], world[1], world[2]}, frame, 0.0);
  int c0, c1, r0, r1;
  if (!cellBox(cam, c0, c1, r0, r1)) {
    return;
  }
  const Eigen::Vector3d a = frame.world_to_camera * world[0];
  const Eigen::Vector3d e1 = frame.world_to_camera * world[1] - a;
  const Eigen::Vector3d e2 = frame.world_to_camera * world[2] - a;
  bool any = false;
  for (int row = r0; row <= r1; ++row) {
    for (int col = c0; col <= c1; ++col) {
      // Moeller-Trumbore ray / triangle intersection, ray from the origin.
      const Eigen::Vector3d ray = cellRay(col, row);
      const Eigen::Vector3d p = ray.cross(e2);
      const double det = e1.dot(p);
      if (std::abs(det) < 1e-15) {
        continue;
      }
      const Eigen::Vector3d q = (-a).cross(e1);
      const double b1 = (-a).dot(p) / det, b2 = ray.dot(q) / det;
      if (b1 < 0 || b2 < 0 || b1 + b2 > 1) {
        continue;
      }
      write(col, row, e2.dot(q) / det, kFineTriangles);
      any = true;
    }
  }
  if (!any) {  // smaller than a cell: it still hides what is behind its centre
    const Eigen::Vector3d centre = (cam[0] + cam[1] + cam[2]) / 3.0;
    const int col =
        static_cast<int>(std::floor((fx_ * centre.x() / centre.z() + cx_ + 0.5) / cell_px_));
    const int row =
        static_cast<int>(std::floor((fy_ * centre.y() / centre.z() + cy_ + 0.5) / cell_px_));
    if (col >= 0 && col < cols_ && row >= 0 && row < rows_) {
      write(col, row, centre.z(), kFineTriangles);
    }
  }
}

bool DepthBuffer::hidden(const Eigen::Vector3d& camera_point, std::int32_t owner,
                         double margin_m) const {
  const double z = camera_point.z();
  const int col = static_cast<int>(std::floor((fx_ * camera_point.x() / z + cx_ + 0.5) / cell_px_));
  const int row = static_cast<int>(std::floor((fy_ * camera_point.y() / z + cy_ + 0.5) / cell_px_));
  if (col < 0 || col >= cols_ || row < 0 || row >= rows_) {
    return false;
  }
  const std::size_t i = index(col, row);
  return owner_[i] != owner && z > depth_[i] + margin_m;
}

}  // namespace pmap::texture
