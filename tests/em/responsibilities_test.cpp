#include "pmap/em/responsibilities.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "em_test_worlds.h"

namespace pmap::em {
namespace {

constexpr double kTolerance = 1e-6;

Surface plane(const Eigen::Vector3d& n, const Eigen::Vector3d& c, double hu, double hv,
              bool bounded = true) {
  Surface s;
  s.rect.normal = n.normalized();
  s.rect.centre = c;
  s.rect.offset = s.rect.normal.dot(c);
  s.rect.axis_u = s.rect.normal.unitOrthogonal();
  s.rect.half_u = hu;
  s.rect.half_v = hv;
  s.rect.bounded = bounded;
  return s;
}

// Three overlapping rectangles, an unbounded plane, and points near and far.
struct Scene {
  std::vector<Surface> surfaces = {
      plane({0, 0, 1}, {0, 0, 0}, 2, 2), plane({0, 0, 1}, {0.5, 0, 0.04}, 1, 1),
      plane({1, 0, 0}, {1.5, 0, 0.5}, 1, 1), plane({0, 1, 0}, {0, 1.2, 0}, 1, 1, false)};
  std::vector<Eigen::Vector3d> points;
  explicit Scene(int n, std::uint64_t seed = 5) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-2.5, 2.5);
    std::normal_distribution<double> g(0.0, 0.05);
    for (int k = 0; k < n; ++k) {
      points.emplace_back(u(rng), u(rng), k % 3 == 0 ? u(rng) : g(rng));
    }
    points.emplace_back(1e6, 1e6, 1e6);    // far from every surface
    points.emplace_back(-1e6, -1e6, 0.0);  // 1e6 m from every plane too
  }
};

Responsibilities eStep(const Scene& s, const MeasurementModel& m, int threads = 1,
                       double tol = kTolerance) {
  Responsibilities r;
  computeResponsibilities(s.points, s.surfaces, RectangleIndex(s.surfaces, m.cutoffDistance(tol)),
                          m, tol, threads, r);
  return r;
}

// Direct log(exp(s*) + sum_j exp(s_ij)) over every surface, by log-sum-exp.
double directLoglik(const Scene& s, const MeasurementModel& m, std::size_t i) {
  double top = m.outlierScore();
  for (const auto& sf : s.surfaces) {
    top = std::max(top, m.surfaceScore(sf.rect.squaredDistance(s.points[i])));
  }
  double sum = std::exp(m.outlierScore() - top);
  for (const auto& sf : s.surfaces) {
    sum += std::exp(m.surfaceScore(sf.rect.squaredDistance(s.points[i])) - top);
  }
  return top + std::log(sum);
}

TEST(Responsibilities, SumToOnePerPoint) {
  const Scene s(3000);
  for (const double sigma : {0.01, 0.05, 0.3}) {
    const MeasurementModel m(sigma, 30.0);
    const Responsibilities r = eStep(s, m);
    ASSERT_EQ(r.points(), s.points.size());
    ASSERT_EQ(r.offsets.size(), s.points.size() + 1);
    for (std::size_t i = 0; i < r.points(); ++i) {
      double sum = r.outlier[i];
      for (std::uint32_t k = r.offsets[i]; k < r.offsets[i + 1]; ++k) {
        EXPECT_GE(r.weight[k], 0.0);
        sum += r.weight[k];
      }
      EXPECT_NEAR(sum, 1.0, 1e-12) << "point " << i;
    }
  }
}

TEST(Responsibilities, LoglikIsTheDirectLogSumExp) {
  const Scene s(3000);
  const MeasurementModel m(0.05, 30.0);
  const Responsibilities r = eStep(s, m);
  double total = 0.0;
  const double J = static_cast<double>(s.surfaces.size());
  for (std::size_t i = 0; i < r.points(); ++i) {
    // Skipped surfaces carry less than the tolerance each: l_i is short of
    // the full sum by at most log(1 + J tol).
    EXPECT_NEAR(r.loglik[i], directLoglik(s, m, i), J * kTolerance) << "point " << i;
    EXPECT_LE(r.loglik[i], directLoglik(s, m, i) + 1e-12);
    // Over the kept entries the E-step is exact.
    double kept = m.outlierScore();
    int best = -1;
    double best_score = m.outlierScore();
    for (std::uint32_t k = r.offsets[i]; k < r.offsets[i + 1]; ++k) {
      kept = logAddExp(kept, r.score[k]);
      EXPECT_DOUBLE_EQ(r.score[k],
                       m.surfaceScore(s.surfaces[r.surface[k]].rect.squaredDistance(s.points[i])));
      if (r.score[k] > best_score) {
        best_score = r.score[k];
        best = r.surface[k];
      }
    }
    EXPECT_NEAR(r.loglik[i], kept, 1e-12);
    EXPECT_EQ(r.best[i], best);
    total += r.loglik[i];
  }
  EXPECT_NEAR(r.total_loglik, total, 1e-9 * std::abs(total));
}

TEST(Responsibilities, SkippedSurfacesHaveResponsibilityBelowTheTolerance) {
  const Scene s(3000);
  const MeasurementModel m(0.02, 30.0);
  const Responsibilities r = eStep(s, m);
  const double cutoff = m.cutoffDistance(kTolerance);
  std::size_t skipped = 0;
  for (std::size_t i = 0; i < r.points(); ++i) {
    const double l = directLoglik(s, m, i);
    for (std::size_t j = 0; j < s.surfaces.size(); ++j) {
      bool listed = false;
      for (std::uint32_t k = r.offsets[i]; k < r.offsets[i + 1]; ++k) {
        listed = listed || r.surface[k] == static_cast<std::int32_t>(j);
      }
      const double d2 = s.surfaces[j].rect.squaredDistance(s.points[i]);
      if (!listed) {
        ++skipped;
        EXPECT_GT(d2, cutoff * cutoff * (1 - 1e-12));
        EXPECT_LT(std::exp(m.surfaceScore(d2) - l), kTolerance);
      } else {
        EXPECT_LE(d2, cutoff * cutoff * (1 + 1e-12));
      }
    }
  }
  EXPECT_GT(skipped, 1000u);
}

TEST(Responsibilities, FarPointsAreOutliersWithoutUnderflow) {
  const Scene s(10);
  for (const double sigma : {0.001, 0.02}) {
    const MeasurementModel m(sigma, 30.0);
    // Even with a tolerance so small that distant surfaces are kept.
    for (const double tol : {kTolerance, 1e-300}) {
      const Responsibilities r = eStep(s, m, 1, tol);
      for (std::size_t i = 0; i < r.points(); ++i) {
        ASSERT_TRUE(std::isfinite(r.loglik[i]));
        ASSERT_TRUE(std::isfinite(r.outlier[i]));
        for (std::uint32_t k = r.offsets[i]; k < r.offsets[i + 1]; ++k) {
          ASSERT_TRUE(std::isfinite(r.weight[k]));
        }
      }
      for (const std::size_t i : {s.points.size() - 2, s.points.size() - 1}) {
        EXPECT_EQ(r.outlier[i], 1.0);
        EXPECT_EQ(r.best[i], -1);
        EXPECT_EQ(r.loglik[i], m.outlierScore());
      }
      EXPECT_TRUE(std::isfinite(r.total_loglik));
    }
  }
}

TEST(Responsibilities, EmptyInputsGiveEmptyOrAllOutlierResults) {
  const MeasurementModel m(0.02, 30.0);
  Responsibilities r;
  computeResponsibilities({}, {}, RectangleIndex(), m, kTolerance, 2, r);
  EXPECT_EQ(r.points(), 0u);
  EXPECT_EQ(r.offsets, std::vector<std::uint32_t>{0});
  EXPECT_EQ(r.total_loglik, 0.0);
  const Scene s(100);
  computeResponsibilities(s.points, {}, RectangleIndex(), m, kTolerance, 2, r);
  for (std::size_t i = 0; i < r.points(); ++i) {
    EXPECT_EQ(r.outlier[i], 1.0);
    EXPECT_EQ(r.best[i], -1);
  }
  EXPECT_TRUE(r.weight.empty());
  EXPECT_NEAR(r.total_loglik, m.outlierScore() * s.points.size(), 1e-9);
}

TEST(Responsibilities, DuplicateSurfacesShareTheirPoints) {
  Scene s(0);
  s.surfaces = {plane({0, 0, 1}, {0, 0, 0}, 1, 1), plane({0, 0, 1}, {0, 0, 0}, 1, 1)};
  s.points = {{0.1, 0.2, 0.0}};
  const MeasurementModel m(0.02, 30.0);
  const Responsibilities r = eStep(s, m);
  ASSERT_EQ(r.offsets[1], 2u);
  EXPECT_DOUBLE_EQ(r.weight[0], r.weight[1]);
  EXPECT_NEAR(r.weight[0], 1.0 / (2.0 + std::exp(m.outlierScore())), 1e-15);
}

TEST(Responsibilities, ResultsDoNotDependOnTheThreadCount) {
  const Scene s(20000);
  const MeasurementModel m(0.03, 30.0);
  const Responsibilities a = eStep(s, m, 1);
  for (const int t : {2, 3, 8}) {
    const Responsibilities b = eStep(s, m, t);
    EXPECT_EQ(a.offsets, b.offsets);
    EXPECT_EQ(a.surface, b.surface);
    EXPECT_EQ(a.weight, b.weight);
    EXPECT_EQ(a.outlier, b.outlier);
    EXPECT_EQ(a.best, b.best);
    EXPECT_EQ(a.loglik, b.loglik);
    EXPECT_EQ(a.total_loglik, b.total_loglik);
  }
}

TEST(LogAddExp, IsStableForLargeAndEqualArguments) {
  EXPECT_DOUBLE_EQ(logAddExp(0.0, 0.0), std::log(2.0));
  EXPECT_DOUBLE_EQ(logAddExp(1000.0, 1000.0), 1000.0 + std::log(2.0));
  EXPECT_DOUBLE_EQ(logAddExp(-1e6, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(logAddExp(-5.0, -std::numeric_limits<double>::infinity()), -5.0);
  EXPECT_NEAR(logAddExp(std::log(3.0), std::log(5.0)), std::log(8.0), 1e-15);
}

// Minor bug (libs/em/src/responsibilities.cpp, logAddExp): with both
// arguments -inf, m = -inf and exp(a - m) = exp(nan), so the result is NaN;
// log(exp(-inf) + exp(-inf)) = log(0) = -inf. The E-step always starts from
// the finite outlier score, so the mapper itself never hits it.
TEST(LogAddExp, BothMinusInfinityGiveMinusInfinity) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(logAddExp(-inf, -inf), -inf);
}

// The numbers of MODEL.md, eq. (11): a point is more outlier than inlier
// beyond sigma sqrt(L*).
TEST(MeasurementModel, OutlierDistancesOfModelMd) {
  EXPECT_NEAR(MeasurementModel(0.05, 8.0).outlierDistance(), 0.144, 0.0005);
  EXPECT_NEAR(MeasurementModel(0.01, 8.0).outlierDistance(), 0.034, 0.0005);
  EXPECT_NEAR(MeasurementModel(0.02, 30.0).outlierDistance(), 0.072, 0.0005);
  EXPECT_NEAR(MeasurementModel(0.05, 30.0).outlierDistance(), 0.165, 0.0005);
  const MeasurementModel m(0.02, 30.0);
  // At the outlier distance the two terms are equal; 1/z_max = N(d; sigma).
  EXPECT_NEAR(m.surfaceScore(std::pow(m.outlierDistance(), 2)), m.outlierScore(), 1e-12);
  EXPECT_NEAR(std::exp(m.outlierScore()) / std::sqrt(2 * M_PI * 0.02 * 0.02), 1.0 / 30.0, 1e-12);
  // At the cutoff a surface's term is `tolerance` times the outlier term.
  EXPECT_NEAR(m.surfaceScore(std::pow(m.cutoffDistance(1e-6), 2)) - m.outlierScore(),
              std::log(1e-6), 1e-9);
}

}  // namespace
}  // namespace pmap::em
