// Occlusion for texturing: a low-resolution depth image of the map seen from
// one camera frame. Each cell holds the depth of the nearest map element on
// the ray through its centre and which element it is (a surface id, or
// kFineTriangles). Cells are laid out on the undistorted (pinhole) image, so
// lookups use undistorted normalised coordinates whatever the lens.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "pmap/products/map_model.h"
#include "pmap/texture/camera_frame.h"
#include "pmap/texture/texture_tile.h"

namespace pmap::texture {

class DepthBuffer {
 public:
  static constexpr std::int32_t kNothing = -1;
  static constexpr std::int32_t kFineTriangles = -2;

  /// Renders `tiles` and `fine` into cells of `cell_px` x `cell_px` image
  /// pixels.
  DepthBuffer(const CameraFrame& frame, const std::vector<TextureTile>& tiles,
              const products::ColoredTriangles& fine, int cell_px);

  /// True when the point `camera_point` (camera frame) on element `owner` is
  /// behind another element by more than `margin_m` along its ray.
  bool hidden(const Eigen::Vector3d& camera_point, std::int32_t owner, double margin_m) const;

  int cols() const { return cols_; }
  int rows() const { return rows_; }
  /// Depth (m along the optical axis) of cell (col, row); +inf if empty.
  float depth(int col, int row) const { return depth_[index(col, row)]; }
  std::int32_t owner(int col, int row) const { return owner_[index(col, row)]; }

 private:
  std::size_t index(int col, int row) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(cols_) +
           static_cast<std::size_t>(col);
  }
  /// Ray (camera frame, z = 1) through the centre of cell (col, row).
  Eigen::Vector3d cellRay(int col, int row) const;
  /// Cell range covered by camera-frame points (pinhole).
  bool cellBox(const std::vector<Eigen::Vector3d>& cam, int& c0, int& c1, int& r0, int& r1) const;
  void renderTile(const TextureTile& tile, const CameraFrame& frame);
  void renderTriangle(const std::array<Eigen::Vector3d, 3>& world, const CameraFrame& frame);
  void write(int col, int row, double depth, std::int32_t owner);

  double fx_, fy_, cx_, cy_;
  int cell_px_;
  int cols_, rows_;
  std::vector<float> depth_;
  std::vector<std::int32_t> owner_;
};

}  // namespace pmap::texture
