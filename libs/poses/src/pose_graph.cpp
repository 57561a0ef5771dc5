#include "pmap/poses/pose_graph.h"

#include <ceres/ceres.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

#include "pmap/common/error.h"

namespace pmap::poses {
namespace {

// An angle: Plus and Minus wrap to [-pi, pi).
class AngleManifold : public ceres::Manifold {
 public:
  int AmbientSize() const override { return 1; }
  int TangentSize() const override { return 1; }
  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override {
    x_plus_delta[0] = detail::wrapped(x[0] + delta[0]);
    return true;
  }
  bool PlusJacobian(const double*, double* jacobian) const override {
    jacobian[0] = 1.0;
    return true;
  }
  bool Minus(const double* y, const double* x, double* y_minus_x) const override {
    y_minus_x[0] = detail::wrapped(y[0] - x[0]);
    return true;
  }
  bool MinusJacobian(const double*, double* jacobian) const override {
    jacobian[0] = 1.0;
    return true;
  }
};

struct EdgeCost {
  Pose2 z;
  Eigen::Matrix3d sqrt_information;
  template <typename T>
  bool operator()(const T* ti, const T* thi, const T* tj, const T* thj, T* residual) const {
    edgeResidual(ti, thi, tj, thj, z, sqrt_information, residual);
    return true;
  }
};

// L^T with I = L L^T (I symmetric positive definite).
Eigen::Matrix3d sqrtInformation(const Eigen::Matrix3d& information) {
  const Eigen::LLT<Eigen::Matrix3d> llt(0.5 * (information + information.transpose()));
  if (llt.info() != Eigen::Success) {
    throw ProcessingError("pose graph: an edge's information matrix is not positive definite");
  }
  return llt.matrixL().transpose();
}

}  // namespace

double wrapAngle(double a) {
  const double w = detail::wrapped(a);
  return w <= -M_PI ? w + 2.0 * M_PI : w;
}

Pose2 compose(const Pose2& a, const Pose2& b) {
  const double c = std::cos(a.theta), s = std::sin(a.theta);
  return {a.x + c * b.x - s * b.y, a.y + s * b.x + c * b.y, wrapAngle(a.theta + b.theta)};
}

Pose2 inverse(const Pose2& a) {
  const double c = std::cos(a.theta), s = std::sin(a.theta);
  return {-c * a.x - s * a.y, s * a.x - c * a.y, wrapAngle(-a.theta)};
}

Pose2 between(const Pose2& a, const Pose2& b) {
  return compose(inverse(a), b);
}

bool PoseGraphOptions::validate(std::string* why) const {
  if (!(loop_loss_scale > 0.0) || !std::isfinite(loop_loss_scale)) {
    *why = "loop_loss_scale must be a finite number > 0";
    return false;
  }
  if (max_iterations < 1) {
    *why = "max_iterations must be >= 1";
    return false;
  }
  return true;
}

std::size_t PoseGraph::addNode(const Pose2& initial) {
  nodes_.push_back(initial);
  return nodes_.size() - 1;
}

void PoseGraph::addEdge(const PoseEdge& edge) {
  edges_.push_back(edge);
}

void PoseGraph::setEdge(std::size_t index, const Pose2& measurement,
                        const Eigen::Matrix3d& information) {
  edges_.at(index).measurement = measurement;
  edges_.at(index).information = information;
}

bool PoseGraph::hasLoops() const {
  return std::any_of(edges_.begin(), edges_.end(), [](const PoseEdge& e) { return e.loop; });
}

double PoseGraph::chi2(const PoseEdge& edge) const {
  const Pose2& a = nodes_[edge.from];
  const Pose2& b = nodes_[edge.to];
  const double ta[2] = {a.x, a.y}, tb[2] = {b.x, b.y};
  double r[3];
  edgeResidual(ta, &a.theta, tb, &b.theta, edge.measurement, sqrtInformation(edge.information), r);
  return r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
}

double PoseGraph::cost() const {
  const double a2 = options_.loop_loss_scale * options_.loop_loss_scale;
  double sum = 0;
  for (const PoseEdge& e : edges_) {
    const double s = chi2(e);
    sum += (e.loop && e.robust) ? a2 * std::log1p(s / a2) : s;  // Ceres' CauchyLoss
  }
  return 0.5 * sum;
}

PoseGraphResult PoseGraph::optimize() {
  PoseGraphResult result;
  if (nodes_.size() < 2 || edges_.empty()) {
    return result;
  }
  std::vector<std::array<double, 2>> t(nodes_.size());
  std::vector<double> theta(nodes_.size());
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    t[i] = {nodes_[i].x, nodes_[i].y};
    theta[i] = nodes_[i].theta;
  }
  ceres::Problem::Options problem_options;
  problem_options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  AngleManifold angle;
  for (const PoseEdge& e : edges_) {
    auto* cost = new ceres::AutoDiffCostFunction<EdgeCost, 3, 2, 1, 2, 1>(
        new EdgeCost{e.measurement, sqrtInformation(e.information)});
    ceres::LossFunction* loss =
        (e.loop && e.robust) ? new ceres::CauchyLoss(options_.loop_loss_scale) : nullptr;
    problem.AddResidualBlock(cost, loss, t[e.from].data(), &theta[e.from], t[e.to].data(),
                             &theta[e.to]);
  }
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (problem.HasParameterBlock(&theta[i])) {
      problem.SetManifold(&theta[i], &angle);
    }
  }
  if (problem.HasParameterBlock(t[0].data())) {
    problem.SetParameterBlockConstant(t[0].data());
    problem.SetParameterBlockConstant(&theta[0]);
  }
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  options.max_num_iterations = options_.max_iterations;
  options.num_threads = 1;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  if (summary.termination_type == ceres::FAILURE) {
    throw ProcessingError("pose graph: Ceres failed: " + summary.message);
  }
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    nodes_[i] = {t[i][0], t[i][1], wrapAngle(theta[i])};
  }
  result.ran = true;
  result.iterations = static_cast<int>(summary.iterations.size());
  result.initial_cost = summary.initial_cost;
  result.final_cost = summary.final_cost;
  result.termination = ceres::TerminationTypeToString(summary.termination_type);
  return result;
}

}  // namespace pmap::poses
