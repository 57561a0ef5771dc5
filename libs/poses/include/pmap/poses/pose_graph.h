// An SE(2) pose graph solved with Ceres: nodes are keyframe poses (x, y,
// theta), edges relative poses with an information matrix. Odometry edges
// (consecutive keyframes, from the front end) use a plain squared loss; loop
// edges a robust (Cauchy) loss, so that one wrong loop cannot bend the
// building. The first node is held fixed (the gauge).
//
// The residual of an edge i -> j with measurement z = (dx, dy, dtheta):
//   e = [ R(theta_i)^T (t_j - t_i) - (dx, dy) ;  wrap(theta_j - theta_i - dtheta) ]
// whitened by the square root of the information matrix (e^T I e = |L^T e|^2).
// Angles live on a manifold that wraps them to (-pi, pi].
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

namespace pmap::poses {

struct Pose2 {
  double x = 0;
  double y = 0;
  double theta = 0;  ///< rad
};

/// a (+) b: b expressed in a's frame, composed.
Pose2 compose(const Pose2& a, const Pose2& b);
/// a^-1
Pose2 inverse(const Pose2& a);
/// a^-1 (+) b: b relative to a.
Pose2 between(const Pose2& a, const Pose2& b);
/// wrapped to (-pi, pi]
double wrapAngle(double a);

struct PoseEdge {
  std::size_t from = 0;
  std::size_t to = 0;
  Pose2 measurement;                                          ///< pose of `to` in `from`'s frame
  Eigen::Matrix3d information = Eigen::Matrix3d::Identity();  ///< (x, y, theta)
  bool loop = false;                                          ///< robust loss
  bool path = false;  ///< (with loop) a path constraint, not a loop closure (path_constraints.h)
  /// (with loop) under the robust loss; false while a new loop is tested
  /// (testLoop in loop_closure.h: the graph must follow it fully to be judged).
  bool robust = true;
};

struct PoseGraphOptions {
  /// Cauchy scale on a loop edge's whitened residual (its chi value): edges
  /// beyond a few of it weigh less and less.
  double loop_loss_scale = 1.0;
  int max_iterations = 100;
  bool validate(std::string* why) const;
};

struct PoseGraphResult {
  bool ran = false;
  int iterations = 0;
  double initial_cost = 0;
  double final_cost = 0;
  std::string termination;  ///< Ceres' termination type
};

class PoseGraph {
 public:
  explicit PoseGraph(PoseGraphOptions options = {}) : options_(options) {}

  /// Adds a node at `initial`; returns its index.
  std::size_t addNode(const Pose2& initial);
  void addEdge(const PoseEdge& edge);
  /// Replaces edge `index`'s measurement and information (same nodes).
  void setEdge(std::size_t index, const Pose2& measurement, const Eigen::Matrix3d& information);
  /// Whether any loop edge is in the graph.
  bool hasLoops() const;

  /// Optimises every node but the first. Throws ProcessingError if Ceres
  /// reports a failure.
  PoseGraphResult optimize();

  std::size_t size() const { return nodes_.size(); }
  const Pose2& node(std::size_t i) const { return nodes_[i]; }
  void setNode(std::size_t i, const Pose2& p) { nodes_[i] = p; }
  const std::vector<PoseEdge>& edges() const { return edges_; }

  /// e^T I e of one edge at the current nodes (its squared Mahalanobis norm).
  double chi2(const PoseEdge& edge) const;
  /// The objective at the current nodes, as Ceres counts it: 1/2 the sum
  /// over edges of rho(e^T I e), rho the Cauchy loss on robust loop edges
  /// and the identity elsewhere.
  double cost() const;

 private:
  PoseGraphOptions options_;
  std::vector<Pose2> nodes_;
  std::vector<PoseEdge> edges_;
};

/// The whitened residual of an edge, for the cost function and its tests:
/// `sqrt_information` is L^T with I = L L^T.
template <typename T>
void edgeResidual(const T* ti, const T* thi, const T* tj, const T* thj, const Pose2& z,
                  const Eigen::Matrix3d& sqrt_information, T* residual);

}  // namespace pmap::poses

#include "pmap/poses/pose_graph_impl.h"
