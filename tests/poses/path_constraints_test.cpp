// Issue 15 (loop and aliasing worlds' bent corridors): keyframe-to-submap
// constraints along the path (path_constraints.h). Against a graph whose
// corridor is bent, they measure the true relative poses; a match the graph
// cannot agree with is dropped; along a bare corridor they claim nothing
// along its axis.
#include "pmap/poses/path_constraints.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "segment_world.h"

namespace pmap::poses {
namespace {

using testing::addBox;
using testing::scan;
using testing::Segment;

constexpr double kDeg = M_PI / 180.0;

// A 50 m corridor 2.4 m wide, with pillars against its walls every 6-8 m
// when `pillars`.
std::vector<Segment> corridor(bool pillars) {
  std::vector<Segment> w = {{{-1, -1.2}, {51, -1.2}}, {{-1, 1.2}, {51, 1.2}}};
  if (pillars) {
    const double at[] = {3.0, 9.5, 16.0, 23.5, 30.0, 37.0, 44.5};
    for (int i = 0; i < 7; ++i) {
      const double y = i % 2 == 0 ? -1.2 : 0.9;
      addBox(w, at[i], y, at[i] + 0.4, y + 0.3);
    }
  }
  return w;
}

struct Drive {
  std::vector<Keyframe> keyframes;
  std::vector<Pose2> truth;
  PoseGraph graph;
};

// Keyframes every 0.5 m along the corridor's centre line (a 30 m laser looking
// ahead: a keyframe 20 m on still sees 10 m of what one saw), the graph's nodes
// bent: lateral offset `bend` x^2, heading 2 `bend` x.
Drive drive(const std::vector<Segment>& world, double bend) {
  std::mt19937 rng(3);
  Drive d;
  for (int i = 0; i < 90; ++i) {
    const double x = 0.5 * i;
    const Pose2 truth{x, 0.0, 0.0};
    Keyframe k;
    k.t = 0.1 * i;
    k.front = truth;
    k.path_m = x;
    k.points = scan(world, truth, rng, 0.01, 30.0);  // the simulator's range
    d.keyframes.push_back(std::move(k));
    d.truth.push_back(truth);
    d.graph.addNode({x, bend * x * x, 2.0 * bend * x});
  }
  return d;
}

std::vector<PoseEdge> constraintsOf(Drive& d, PathConstraints& c) {
  for (std::size_t i = 0; i < d.keyframes.size(); ++i) {
    c.add(i, d.keyframes, d.graph);
  }
  return c.edges();
}

double rmsError(const PoseGraph& graph, const std::vector<Pose2>& truth) {
  double sum = 0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    sum += std::pow(graph.node(i).x - truth[i].x, 2) + std::pow(graph.node(i).y - truth[i].y, 2);
  }
  return std::sqrt(sum / static_cast<double>(truth.size()));
}

// A chain whose edges bend a little each (as consecutive keyframe edges
// matched against the last few metres do), with the information of a
// refined keyframe edge held to calibrated odometry (5 mm, 0.1 deg):
// solved with the path constraints, a good part of the bend goes (measured:
// half of it; the constraints' own headings are good to about 0.08 deg here,
// as good as the bent chain's over 10-20 m).
TEST(PathConstraints, StraightenABentChain) {
  Drive d = drive(corridor(true), 5e-5);  // 0.1 m off at 44 m, 0.25 deg
  PathConstraints c(PathConstraintOptions{}, ScanRefineOptions{});
  const std::vector<PoseEdge> constraints = constraintsOf(d, c);
  // up to four per keyframe once 20 m are behind (260); the farthest see
  // little of the same walls
  ASSERT_GT(constraints.size(), 130u);
  for (const PoseEdge& e : constraints) {
    EXPECT_TRUE(e.loop && e.path);
  }
  const double bent = rmsError(d.graph, d.truth);
  const Eigen::Matrix3d chain_information =
      Eigen::Vector3d(1.0 / 25e-6, 1.0 / 25e-6, 1.0 / std::pow(0.1 * kDeg, 2)).asDiagonal();
  for (std::size_t i = 1; i < d.truth.size(); ++i) {
    PoseEdge e;
    e.from = i - 1;
    e.to = i;
    e.measurement = between(d.graph.node(i - 1), d.graph.node(i));
    e.information = chain_information;
    d.graph.addEdge(e);
  }
  for (const PoseEdge& e : constraints) {
    d.graph.addEdge(e);
  }
  d.graph.optimize();
  const double solved = rmsError(d.graph, d.truth);
  std::printf("RMS error: bent chain %.4f m, solved with %zu path constraints %.4f m\n", bent,
              constraints.size(), solved);
  EXPECT_LT(solved, 0.7 * bent);
  EXPECT_EQ(c.rejected(), 0u);
}

TEST(PathConstraints, AMatchTheGraphCannotAgreeWithIsDropped) {
  Drive d = drive(corridor(true), 0.0);
  // One node 0.2 m off across the corridor: within the matches' reach (0.3
  // m), so its constraints are made, and they disagree. (0.5 m, beyond that
  // reach, left it to the pillars whether a match was made at all; with
  // one-sided normals none was, and nothing was there to drop.)
  Pose2 wrong = d.graph.node(50);
  wrong.y += 0.2;
  d.graph.setNode(50, wrong);
  PathConstraints c(PathConstraintOptions{}, ScanRefineOptions{});
  const std::vector<PoseEdge> edges = constraintsOf(d, c);
  EXPECT_GT(c.rejected(), 0u);
  for (const PoseEdge& e : edges) {
    EXPECT_NE(e.to, 50u);
  }
}

TEST(PathConstraints, ABareCorridorClaimsNothingAlongItsAxis) {
  Drive d = drive(corridor(false), 0.0);
  PathConstraints c(PathConstraintOptions{}, ScanRefineOptions{});
  const std::vector<PoseEdge> edges = constraintsOf(d, c);
  ASSERT_FALSE(edges.empty());
  for (const PoseEdge& e : edges) {
    // the flat prior's trace only (1e-3 / m^2), against thousands across
    EXPECT_LT(e.information(0, 0), 0.01);
    EXPECT_GT(e.information(1, 1), 100.0);
  }
}

TEST(PathConstraints, NoneWhenTurnedOff) {
  Drive d = drive(corridor(true), 0.0);
  PathConstraintOptions off;
  off.count = 0;
  PathConstraints c(off, ScanRefineOptions{});
  EXPECT_TRUE(constraintsOf(d, c).empty());
}

TEST(PathConstraintOptions, ValidateRejectsNonsense) {
  std::string why;
  EXPECT_TRUE(PathConstraintOptions{}.validate(&why)) << why;
  PathConstraintOptions o;
  o.count = -1;
  EXPECT_FALSE(o.validate(&why));
  o = {};
  o.spacing_m = 0.0;
  EXPECT_FALSE(o.validate(&why));
  o = {};
  o.max_chi2 = std::nan("");
  EXPECT_FALSE(o.validate(&why));
  o = {};
  o.min_along_ratio = 2.0;
  EXPECT_FALSE(o.validate(&why));
  o = {};
  o.max_gap_m = -1.0;
  EXPECT_FALSE(o.validate(&why));
}

}  // namespace
}  // namespace pmap::poses
