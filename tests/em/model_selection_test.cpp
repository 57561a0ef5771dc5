#include "pmap/em/model_selection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "em_test_worlds.h"
#include "pmap/em/surface_fit.h"

namespace pmap::em {
namespace {

using testing::allIndices;

using Scoring = PlanarEmOptions::Scoring;

// A 4 m x 4 m ceiling grid, with an L-shaped variant (arms 1.5 m wide).
testing::Cloud ceiling(bool l_shaped) {
  testing::Cloud c;
  std::mt19937_64 rng(1);
  testing::addPlane(c, {0, 0, 2.5}, {1, 0, 0}, {0, 1, 0}, 4.0, 4.0, 0.05, 0.0, rng, 0,
                    [l_shaped](double s, double t) { return !l_shaped || s <= 1.5 || t <= 1.5; });
  return c;
}

Rectangle fitted(const testing::Cloud& c) {
  Rectangle r;
  EXPECT_EQ(fitSurface(c.points, allIndices(c.points.size()), r), FitStatus::kOk);
  return r;
}

TEST(EmptyArea, AFullyCoveredRectangleHasNone) {
  const testing::Cloud c = ceiling(false);
  const Rectangle r = fitted(c);
  EXPECT_NEAR(r.area(), 16.0, 1e-9);
  EXPECT_EQ(emptyArea(c.points, allIndices(c.points.size()), r, 0.15), 0.0);
}

TEST(EmptyArea, AnLShapeLeavesItsMissingQuadrant) {
  const testing::Cloud c = ceiling(true);
  const Rectangle r = fitted(c);
  // Cells are counted whole: along the L's 16 m of boundary the covered area
  // is overestimated by up to a cell's width, so the empty area is within
  // [6.25 - 16 cell, 6.25] and approaches 6.25 as cells shrink (while they
  // still hold points: 2 x the 5 cm spacing here).
  double previous_error = 1e9;
  for (const double cell : {0.3, 0.15, 0.1}) {
    const double empty = emptyArea(c.points, allIndices(c.points.size()), r, cell);
    EXPECT_LE(empty, 6.25 + 1e-9) << "cell " << cell;
    EXPECT_GE(empty, 6.25 - 16 * cell) << "cell " << cell;
    EXPECT_LT(6.25 - empty, previous_error) << "cell " << cell;
    previous_error = 6.25 - empty;
  }
}

TEST(EmptyArea, NoMembersOrUnboundedPlanes) {
  const testing::Cloud c = ceiling(false);
  Rectangle r = fitted(c);
  EXPECT_NEAR(emptyArea(c.points, {}, r, 0.15), 16.0, 1e-9);
  r.bounded = false;
  EXPECT_EQ(emptyArea(c.points, {}, r, 0.15), 0.0);
}

TEST(LogPosterior, IsLikelihoodMinusKappaJMinusEmptyAreaCost) {
  Responsibilities r;
  r.total_loglik = -1234.5;
  PlanarEmOptions o;
  o.kappa = 7.0;
  o.empty_area_cost = 3.0;
  EXPECT_DOUBLE_EQ(logPosterior(r, std::vector<Surface>(2), {1.0, 0.5}, o), -1234.5 - 14.0 - 4.5);
  EXPECT_DOUBLE_EQ(logPosterior(r, {}, {}, o), -1234.5);
}

TEST(CombineScores, SoftIsLogSumExpHardIsMax) {
  EXPECT_DOUBLE_EQ(combineScores(-1.0, -3.0, Scoring::kHard), -1.0);
  EXPECT_NEAR(combineScores(-1.0, -3.0, Scoring::kSoft), std::log(std::exp(-1.0) + std::exp(-3.0)),
              1e-15);
}

// Points near a wall; surface 0 is the wall, surface 1 a rectangle beside it.
struct Scene {
  testing::Cloud cloud;
  std::vector<Surface> surfaces;
  MeasurementModel model{0.02, 30.0};
  Scene() {
    std::mt19937_64 rng(3);
    testing::addPlane(cloud, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 3.0, 2.0, 0.05, 0.03, rng, 0);
    Surface wall;
    wall.rect.normal = {0, 1, 0};
    wall.rect.axis_u = {1, 0, 0};
    wall.rect.centre = {1.5, 0.01, 1.0};
    wall.rect.offset = 0.01;
    wall.rect.half_u = 1.2;
    wall.rect.half_v = 1.0;
    Surface part = wall;
    part.rect.centre = {2.6, 0.03, 1.0};
    part.rect.offset = 0.03;
    part.rect.half_u = 0.4;
    surfaces = {wall, part};
  }
  Responsibilities expect(const std::vector<Surface>& s) const {
    Responsibilities r;
    computeResponsibilities(cloud.points, s, RectangleIndex(s, model.cutoffDistance(1e-6)), model,
                            1e-6, 1, r);
    return r;
  }
  // Sum over points of the hard score max(s*, max_j s_ij) (entries kept).
  double hardTotal(const Responsibilities& r) const {
    double t = 0.0;
    for (std::size_t i = 0; i < r.points(); ++i) {
      t += pointScore(r, i, model.outlierScore(), Scoring::kHard);
    }
    return t;
  }
};

TEST(PointScore, SoftIsTheLoglikAndSkipLeavesOutOneEntry) {
  const Scene s;
  const Responsibilities r = s.expect(s.surfaces);
  const double s_star = s.model.outlierScore();
  for (std::size_t i = 0; i < r.points(); i += 7) {
    EXPECT_NEAR(pointScore(r, i, s_star, Scoring::kSoft), r.loglik[i], 1e-12);
    double hard = s_star;
    for (std::uint32_t k = r.offsets[i]; k < r.offsets[i + 1]; ++k) {
      hard = std::max(hard, r.score[k]);
    }
    EXPECT_DOUBLE_EQ(pointScore(r, i, s_star, Scoring::kHard), hard);
    if (r.offsets[i + 1] - r.offsets[i] == 1) {
      EXPECT_DOUBLE_EQ(pointScore(r, i, s_star, Scoring::kSoft, r.offsets[i]), s_star);
    }
  }
}

TEST(LogLikelihoodChange, MatchesARecomputedEStep) {
  const Scene s;
  const Responsibilities with_wall = s.expect({s.surfaces[0]});
  const Responsibilities with_both = s.expect(s.surfaces);
  const Responsibilities with_part = s.expect({s.surfaces[1]});
  const auto all = allIndices(s.cloud.points.size());
  // Adding the part to the wall.
  EXPECT_NEAR(logLikelihoodChange(s.cloud.points, with_wall, s.model, all, {}, {s.surfaces[1].rect},
                                  1e-6, Scoring::kSoft),
              with_both.total_loglik - with_wall.total_loglik, 1e-7);
  EXPECT_NEAR(logLikelihoodChange(s.cloud.points, with_wall, s.model, all, {}, {s.surfaces[1].rect},
                                  1e-6, Scoring::kHard),
              s.hardTotal(with_both) - s.hardTotal(with_wall), 1e-7);
  // Removing the wall (surface 0) from both.
  for (const Scoring sc : {Scoring::kSoft, Scoring::kHard}) {
    const double expected = sc == Scoring::kSoft ? with_part.total_loglik - with_both.total_loglik
                                                 : s.hardTotal(with_part) - s.hardTotal(with_both);
    EXPECT_NEAR(logLikelihoodChange(s.cloud.points, with_both, s.model, all, {0}, {}, 1e-6, sc),
                expected, 1e-7);
  }
  // Nothing changed, or no affected points: zero.
  EXPECT_EQ(
      logLikelihoodChange(s.cloud.points, with_both, s.model, all, {}, {}, 1e-6, Scoring::kSoft),
      0.0);
  EXPECT_EQ(
      logLikelihoodChange(s.cloud.points, with_both, s.model, {}, {0}, {}, 1e-6, Scoring::kSoft),
      0.0);
}

TEST(DistinctRows, CountsRowsOfTheMembers) {
  EXPECT_EQ(distinctRows({}, {0, 1}), 0u);
  const std::vector<std::int32_t> rows = {3, 3, 4, 9, 4, 3};
  EXPECT_EQ(distinctRows(rows, {}), 0u);
  EXPECT_EQ(distinctRows(rows, {0, 1, 5}), 1u);
  EXPECT_EQ(distinctRows(rows, {5, 2, 3, 0}), 3u);
}

TEST(PointsNear, MatchesBruteForce) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  std::vector<Eigen::Vector3d> pts;
  for (int k = 0; k < 5000; ++k) {
    pts.emplace_back(u(rng), u(rng), 0.2 * u(rng));
  }
  const PointGrid grid(pts, 0.5);
  for (int t = 0; t < 10; ++t) {
    Rectangle r;
    const Eigen::Isometry3d T = testing::randomMotion(rng, 1.0);
    r.normal = T.linear().col(2);
    r.axis_u = T.linear().col(0);
    r.centre = T.translation();
    r.offset = r.normal.dot(r.centre);
    r.half_u = 0.1 * t;
    r.half_v = 0.5;
    std::vector<std::int32_t> brute;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      if (r.squaredDistance(pts[i]) <= 0.15 * 0.15) {
        brute.push_back(static_cast<std::int32_t>(i));
      }
    }
    EXPECT_EQ(pointsNear(grid, pts, r, 0.15), brute);
  }
}

TEST(UnionOf, IsSortedAndWithoutDuplicates) {
  EXPECT_TRUE(unionOf({}).empty());
  EXPECT_TRUE(unionOf({{}, {}}).empty());
  EXPECT_EQ(unionOf({{5, 1, 3}, {3, 2}, {}, {9, 1}}), (std::vector<std::int32_t>{1, 2, 3, 5, 9}));
}

// A rectangle stretched over 1e7 to 1e12 m by stray members: the covered
// cells are counted from the members (a sorted list, not a grid over the
// rectangle), each distinct cell once, without overflow.
TEST(EmptyArea, Item12_AStretchedRectangleCountsTheMembersCells) {
  for (const double far_m : {500.0, 1e7, 1e9, 1e12}) {  // all beyond the dense grid's limit
    SCOPED_TRACE(far_m);
    std::vector<Eigen::Vector3d> pts = {
        {0.01, 0.01, 0}, {0.02, 0.02, 0}, {0.5, 0.01, 0}, {far_m, far_m, 0}, {far_m, far_m, 0}};
    Rectangle r;
    r.centre = {far_m / 2, far_m / 2, 0};
    r.half_u = r.half_v = far_m / 2;
    const double cell = 0.1;
    // Distinct cells: (0, 0), (5, 0) and the far corner's.
    const double covered = 3 * cell * cell;
    EXPECT_DOUBLE_EQ(emptyArea(pts, allIndices(pts.size()), r, cell), r.area() - covered);
  }
}

}  // namespace
}  // namespace pmap::em
