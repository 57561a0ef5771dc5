// Nearest-triangle distances for the accuracy figures (map_accuracy.h): a
// uniform grid over triangles (points are triangles with three equal
// corners), searched in growing shells of cells around the query.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace pmap::eval {

struct Triangle3 {
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
};

/// The closest point of triangle t to p (Ericson, Real-Time Collision
/// Detection, 5.1.5); degenerate triangles (segments, points) included.
Eigen::Vector3d closestPointOnTriangle(const Triangle3& t, const Eigen::Vector3d& p);

struct TriangleIndexOptions {
  double cell_m = 0.25;         ///< grid cell edge (m)
  double max_distance_m = 3.0;  ///< search radius; farther distances are reported as this (m)
  bool validate(std::string* why) const;
};

class TriangleIndex {
 public:
  /// Throws std::invalid_argument when the options are invalid or a corner
  /// is not finite.
  TriangleIndex(std::vector<Triangle3> triangles, const TriangleIndexOptions& options);

  /// Distance from p to the nearest triangle, at most max_distance_m (also
  /// when there are no triangles).
  double distance(const Eigen::Vector3d& p) const;
  std::size_t size() const { return triangles_.size(); }

 private:
  using Key = std::int64_t;
  Key key(std::int64_t x, std::int64_t y, std::int64_t z) const;
  Eigen::Array3i cellOf(const Eigen::Vector3d& p) const;
  void insert(std::uint32_t k);
  double scanCell(const Eigen::Array3i& c, const Eigen::Vector3d& p, double best) const;

  std::vector<Triangle3> triangles_;
  TriangleIndexOptions options_;
  std::unordered_map<Key, std::vector<std::uint32_t>> cells_;
  /// The box of the cells that hold a triangle (none outside it).
  Eigen::Array3i lo_ = Eigen::Array3i::Constant(1), hi_ = Eigen::Array3i::Constant(0);
};

}  // namespace pmap::eval
