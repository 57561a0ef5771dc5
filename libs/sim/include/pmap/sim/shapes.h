// The simulator's primitives and its own ray intersection code (Eigen only):
// rectangles with rectangular holes, vertical cylinders and vertical boxes.
// Rays are origin + t * dir with t in (t_min, t_max]; `dir` need not be unit
// length (t is then in units of |dir|: the renderer uses dir.z() = 1 so that t
// is the depth). Solids (cylinder, box) are hit on their surface: from outside
// at the entry point, from inside at the exit point. Rectangles are two-sided.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <vector>

namespace pmap::sim {

/// A rectangular opening in a rectangle, in its (u, v) frame, metres.
struct HoleRange {
  double u0 = 0.0;
  double u1 = 0.0;
  double v0 = 0.0;
  double v1 = 0.0;
};

/// A rectangle: corner 0 at `origin`, unit edge directions `axis_u`, `axis_v`
/// (orthogonal), side lengths in metres. Corners in order: origin, +u, +u+v, +v.
/// Its normal is axis_u x axis_v.
struct Rectangle3 {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis_u = Eigen::Vector3d::UnitX();
  Eigen::Vector3d axis_v = Eigen::Vector3d::UnitY();
  double length_u = 0.0;
  double length_v = 0.0;
  std::vector<HoleRange> holes;

  Eigen::Vector3d normal() const { return axis_u.cross(axis_v); }
  Eigen::Vector3d centre() const { return origin + 0.5 * (length_u * axis_u + length_v * axis_v); }
  Eigen::Vector3d at(double u, double v) const { return origin + u * axis_u + v * axis_v; }
  std::array<Eigen::Vector3d, 4> corners() const;
  std::array<Eigen::Vector3d, 4> holeCorners(const HoleRange& hole) const;
  /// (u, v) of the orthogonal projection of p, metres.
  Eigen::Vector2d toLocal(const Eigen::Vector3d& p) const;
  /// True if (u, v) lies in the rectangle and in none of its holes.
  bool containsLocal(double u, double v) const;

  /// From three corners c0, c1 (along u) and c3 (along v); c2 is implied.
  /// Requires orthogonal, non-degenerate edges (asserted).
  static Rectangle3 fromCorners(const Eigen::Vector3d& c0, const Eigen::Vector3d& c1,
                                const Eigen::Vector3d& c3);
  /// Like fromCorners, but ordered so that the normal points towards
  /// `free_space_point` (u is reversed if needed).
  static Rectangle3 facing(const Eigen::Vector3d& c0, const Eigen::Vector3d& c1,
                           const Eigen::Vector3d& c3, const Eigen::Vector3d& free_space_point);
};

/// A solid vertical cylinder (axis parallel to +Z).
struct VerticalCylinder {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius_m = 0.0;
  double z_min_m = 0.0;
  double z_max_m = 0.0;
};

/// A solid box with vertical sides, rotated by `yaw_rad` about +Z.
struct VerticalBox {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  Eigen::Vector2d half_size_m = Eigen::Vector2d::Zero();
  double yaw_rad = 0.0;
  double z_min_m = 0.0;
  double z_max_m = 0.0;
};

struct ShapeHit {
  double t = 0.0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< geometric normal (not flipped to the ray)
  Eigen::Vector2d local = Eigen::Vector2d::Zero();    ///< texture coordinates, metres
};

/// Parallel (grazing) rays miss; a hit inside a hole misses.
std::optional<ShapeHit> intersectRectangle(const Rectangle3& rect, const Eigen::Vector3d& origin,
                                           const Eigen::Vector3d& dir, double t_min, double t_max);
std::optional<ShapeHit> intersectCylinder(const VerticalCylinder& cyl,
                                          const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                                          double t_min, double t_max);
std::optional<ShapeHit> intersectBox(const VerticalBox& box, const Eigen::Vector3d& origin,
                                     const Eigen::Vector3d& dir, double t_min, double t_max);

}  // namespace pmap::sim
