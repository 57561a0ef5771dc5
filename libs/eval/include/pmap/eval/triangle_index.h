// Nearest-triangle distances for the accuracy figures (map_accuracy.h): a
// bounding-box tree over the triangles (points are triangles with three
// equal corners), searched nearest box first; a box no nearer than the best
// distance so far is skipped with all it holds. The distance is the exact
// minimum over every triangle (capped), whatever the tree's shape.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <string>
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
  /// A box of the tree: its children, or (leaf) a range of order_.
  struct Node {
    Eigen::AlignedBox3d box;
    std::int32_t left = -1;  ///< -1: a leaf
    std::int32_t right = -1;
    std::uint32_t first = 0;  ///< leaf: order_[first, first + count)
    std::uint32_t count = 0;
  };
  std::int32_t build(std::uint32_t first, std::uint32_t count);

  std::vector<Triangle3> triangles_;
  TriangleIndexOptions options_;
  std::vector<Eigen::AlignedBox3d> boxes_;  ///< per triangle
  std::vector<std::uint32_t> order_;        ///< triangle indices, grouped by leaf
  std::vector<Node> nodes_;                 ///< nodes_[0]: the root
};

}  // namespace pmap::eval
