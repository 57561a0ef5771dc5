// Issue 15: the SE(2) pose graph's residual, its derivatives and its solve.
#include "pmap/poses/pose_graph.h"

#include <ceres/ceres.h>
#include <ceres/gradient_checker.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace pmap::poses {
namespace {

struct Residual {
  Pose2 z;
  Eigen::Matrix3d sqrt_information;
  template <typename T>
  bool operator()(const T* ti, const T* thi, const T* tj, const T* thj, T* r) const {
    edgeResidual(ti, thi, tj, thj, z, sqrt_information, r);
    return true;
  }
};

PoseEdge edge(std::size_t from, std::size_t to, const Pose2& z, bool loop = false) {
  PoseEdge e;
  e.from = from;
  e.to = to;
  e.measurement = z;
  e.information = Eigen::Vector3d(400.0, 400.0, 3000.0).asDiagonal();
  e.loop = loop;
  return e;
}

TEST(PoseAlgebra, ComposeBetweenAndInverseAgree) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int i = 0; i < 100; ++i) {
    const Pose2 a{u(rng), u(rng), u(rng)}, b{u(rng), u(rng), u(rng)};
    const Pose2 ab = compose(a, between(a, b));
    EXPECT_NEAR(ab.x, b.x, 1e-12);
    EXPECT_NEAR(ab.y, b.y, 1e-12);
    EXPECT_NEAR(wrapAngle(ab.theta - b.theta), 0.0, 1e-12);
    const Pose2 id = compose(a, inverse(a));
    EXPECT_NEAR(std::hypot(id.x, id.y), 0.0, 1e-12);
    EXPECT_NEAR(wrapAngle(id.theta), 0.0, 1e-12);
  }
  EXPECT_DOUBLE_EQ(wrapAngle(3.0 * M_PI), M_PI);  // (-pi, pi]
  EXPECT_DOUBLE_EQ(wrapAngle(-M_PI), M_PI);
}

// chi2 = e^T I e for a full (non-diagonal) information matrix, and zero at
// the measurement, also across the angle wrap.
TEST(PoseGraph, Chi2IsTheMahalanobisNormOfTheResidual) {
  PoseGraph g;
  const Pose2 a{1.0, 2.0, 3.0}, b{-0.5, 4.0, -3.0};  // theta difference wraps
  g.addNode(a);
  g.addNode(b);
  PoseEdge e = edge(0, 1, between(a, b));
  e.information << 50, 10, 2, 10, 80, -3, 2, -3, 900;
  EXPECT_NEAR(g.chi2(e), 0.0, 1e-18);
  const Pose2 off{0.03, -0.02, 0.01};
  e.measurement = compose(between(a, b), off);
  const Pose2 z = e.measurement;
  const Pose2 rel = between(a, b);
  const Eigen::Vector3d err(rel.x - z.x, rel.y - z.y, wrapAngle(rel.theta - z.theta));
  EXPECT_NEAR(g.chi2(e), err.dot(e.information * err), 1e-9);
}

// Autodiff derivatives of the residual equal numeric ones (Ceres'
// GradientChecker), also near the angle wrap.
TEST(PoseGraph, ResidualDerivativesMatchNumericOnes) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int trial = 0; trial < 20; ++trial) {
    double ti[2] = {u(rng), u(rng)}, tj[2] = {u(rng), u(rng)};
    double thi = trial % 2 ? 3.1 : u(rng), thj = trial % 2 ? -3.1 : u(rng);
    const Eigen::Matrix3d l = (Eigen::Matrix3d() << 5, 0, 0, 1, 7, 0, 0.5, -1, 30).finished();
    ceres::AutoDiffCostFunction<Residual, 3, 2, 1, 2, 1> cost(
        new Residual{{u(rng), u(rng), u(rng)}, l.transpose()});
    const std::vector<const ceres::Manifold*>* no_manifolds = nullptr;
    ceres::GradientChecker checker(&cost, no_manifolds, ceres::NumericDiffOptions());
    ceres::GradientChecker::ProbeResults results;
    const double* params[] = {ti, &thi, tj, &thj};
    // Ceres' numeric derivatives are good to about 1e-5 here; a wrong
    // analytic term would be off by order one.
    EXPECT_TRUE(checker.Probe(params, 1e-4, &results)) << results.error_log;
  }
}

// A square driven with a heading bias that the odometry edges' heading
// sigma (0.05 rad) admits: the loop edge pulls the last corner back, and
// every odometry edge takes a share.
TEST(PoseGraph, ALoopEdgeRemovesTheDrift) {
  const Pose2 truth[] = {{0, 0, 0}, {4, 0, M_PI / 2}, {4, 4, M_PI}, {0, 4, -M_PI / 2}};
  PoseGraph g;
  Pose2 drifted = truth[0];
  g.addNode(drifted);
  for (int i = 1; i < 4; ++i) {
    Pose2 step = between(truth[i - 1], truth[i]);
    step.theta += 0.05;  // about 3 degrees of bias per corner
    drifted = compose(drifted, step);
    g.addNode(drifted);
    PoseEdge odometry = edge(static_cast<std::size_t>(i - 1), static_cast<std::size_t>(i), step);
    odometry.information(2, 2) = 1.0 / (0.05 * 0.05);
    g.addEdge(odometry);
  }
  const double before = std::hypot(g.node(3).x - truth[3].x, g.node(3).y - truth[3].y);
  g.addEdge(edge(0, 3, between(truth[0], truth[3]), true));
  const PoseGraphResult r = g.optimize();
  ASSERT_TRUE(r.ran);
  EXPECT_LT(r.final_cost, r.initial_cost);
  const double after = std::hypot(g.node(3).x - truth[3].x, g.node(3).y - truth[3].y);
  EXPECT_GT(before, 0.4);
  EXPECT_LT(after, 0.25 * before);
  EXPECT_DOUBLE_EQ(g.node(0).x, 0.0);  // the gauge stays
}

// A loop the odometry cannot agree with keeps a large residual under the
// Cauchy loss.
TEST(PoseGraph, AWrongLoopStaysVisible) {
  PoseGraph g;
  for (int i = 0; i < 6; ++i) {
    g.addNode({static_cast<double>(i), 0.0, 0.0});
    if (i > 0) {
      g.addEdge(edge(static_cast<std::size_t>(i - 1), static_cast<std::size_t>(i), {1.0, 0, 0}));
    }
  }
  const PoseEdge wrong = edge(0, 5, {2.0, 3.0, 1.0}, true);  // 3 m and 57 deg off
  g.addEdge(wrong);
  g.optimize();
  EXPECT_GT(g.chi2(wrong), 100.0);
  EXPECT_LT(std::abs(g.node(5).x - 5.0), 0.5);  // the chain held
}

// An edge made again (odometry_model.h's remake): same nodes, new
// measurement and information; a path constraint counts as a loop edge.
TEST(PoseGraph, EdgesAreReplacedAndPathConstraintsAreLoopEdges) {
  PoseGraph g;
  g.addNode({});
  g.addNode({1.0, 0.0, 0.0});
  g.addNode({2.0, 0.0, 0.0});
  g.addEdge(edge(0, 1, {1.0, 0, 0}));
  g.addEdge(edge(1, 2, {1.0, 0, 0}));
  EXPECT_FALSE(g.hasLoops());
  g.setEdge(1, {1.1, 0.0, 0.0}, Eigen::Matrix3d::Identity() * 7.0);
  EXPECT_EQ(g.edges()[1].from, 1u);
  EXPECT_DOUBLE_EQ(g.edges()[1].measurement.x, 1.1);
  EXPECT_DOUBLE_EQ(g.edges()[1].information(2, 2), 7.0);
  EXPECT_THROW(g.setEdge(2, {}, Eigen::Matrix3d::Identity()), std::out_of_range);
  PoseEdge constraint = edge(0, 2, {2.1, 0, 0}, true);
  constraint.path = true;
  g.addEdge(constraint);
  EXPECT_TRUE(g.hasLoops());
}

// cost() is the objective Ceres minimises (1/2 the sum of rho(e^T I e)),
// with the Cauchy loss on robust loop edges only.
TEST(PoseGraph, CostIsCeresObjective) {
  PoseGraph g;
  for (int i = 0; i < 5; ++i) {
    g.addNode({1.02 * i, 0.01 * i, 0.02 * i});
    if (i > 0) {
      g.addEdge(edge(static_cast<std::size_t>(i - 1), static_cast<std::size_t>(i), {1.0, 0, 0}));
    }
  }
  g.addEdge(edge(0, 4, {4.3, 0.2, 0.0}, true));
  PoseEdge plain = edge(1, 3, {2.1, -0.1, 0.05}, true);
  plain.robust = false;
  g.addEdge(plain);
  double expected = 0;
  for (const PoseEdge& e : g.edges()) {
    const double s = g.chi2(e);
    expected += 0.5 * ((e.loop && e.robust) ? std::log1p(s) : s);  // Cauchy scale 1
  }
  EXPECT_NEAR(g.cost(), expected, 1e-12);
  const PoseGraphResult r = g.optimize();
  EXPECT_NEAR(g.cost(), r.final_cost, 1e-9 * (1.0 + r.final_cost));
}

// The loop test's innovation (loop_closure.cpp, testLoop): the rise
// of the objective when the graph follows a new loop under a plain cost is
// e^T (Sigma_chain + Sigma_loop)^-1 e. A straight chain of n edges, each
// sigma_t in x and y and a heading held tight, gives a relative position
// covariance of n sigma_t^2 I between its ends.
TEST(PoseGraph, Item15_TheCostRiseOfALoopIsItsMahalanobisInnovation) {
  const int n = 20;
  const double sigma_t = 0.02, sigma_loop = 0.05;
  PoseGraph g;
  for (int i = 0; i <= n; ++i) {
    g.addNode({0.5 * i, 0.0, 0.0});
    if (i > 0) {
      PoseEdge e = edge(static_cast<std::size_t>(i - 1), static_cast<std::size_t>(i), {0.5, 0, 0});
      e.information =
          Eigen::Vector3d(1 / (sigma_t * sigma_t), 1 / (sigma_t * sigma_t), 1e9).asDiagonal();
      g.addEdge(e);
    }
  }
  const Eigen::Vector2d offset(0.12, -0.05);  // the loop's error against the chain
  PoseEdge loop =
      edge(0, static_cast<std::size_t>(n), {0.5 * n + offset.x(), offset.y(), 0.0}, true);
  loop.information =
      Eigen::Vector3d(1 / (sigma_loop * sigma_loop), 1 / (sigma_loop * sigma_loop), 1e9)
          .asDiagonal();
  loop.robust = false;
  const double before = g.cost();
  g.addEdge(loop);
  g.optimize();
  const double innovation = 2.0 * (g.cost() - before);
  const double expected = offset.squaredNorm() / (n * sigma_t * sigma_t + sigma_loop * sigma_loop);
  EXPECT_NEAR(innovation, expected, 0.01 * expected);
}

}  // namespace
}  // namespace pmap::poses
