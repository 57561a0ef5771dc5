// The residuals themselves (values against hand-worked geometry) and their
// automatic derivatives against numeric ones (ceres::GradientChecker, with
// the normal on its SphereManifold).
#include "pmap/refine/cost_functions.h"

#include <ceres/ceres.h>
#include <ceres/gradient_checker.h>
#include <gtest/gtest.h>

#include <memory>
#include <random>

namespace pmap::refine {
namespace {

// A tilted, rotated surface so that no derivative is trivially zero.
SurfaceParams tiltedSurface() {
  em::Rectangle r;
  r.normal = Eigen::Vector3d(0.1, 0.95, 0.2).normalized();
  r.centre = Eigen::Vector3d(1.0, 2.0, 1.5);
  r.offset = r.normal.dot(r.centre);
  r.axis_u = r.normal.cross(Eigen::Vector3d::UnitZ()).normalized();
  r.half_u = 1.5;
  r.half_v = 1.0;
  SurfaceParams p = SurfaceParams::fromRectangle(r);
  p.rotation = 0.05;
  return p;
}

// Probes `cost` at `blocks`; the blocks of size 3 are normals (sphere).
// Each derivative (in the manifold's tangent space) must match the numeric
// one to 1e-6 relative, or 1e-6 absolute where both are ~0 (a derivative
// that is exactly zero, e.g. of an in-plane coordinate along the normal,
// differs from its numeric estimate by rounding only).
void expectGradientsMatch(const ceres::CostFunction& cost, const std::vector<double*>& blocks) {
  ceres::SphereManifold<3> sphere;
  std::vector<const ceres::Manifold*> manifolds;
  for (const int size : cost.parameter_block_sizes()) {
    manifolds.push_back(size == 3 ? &sphere : nullptr);
  }
  ceres::NumericDiffOptions numeric;
  numeric.ridders_relative_initial_step_size = 1e-3;
  ceres::GradientChecker checker(&cost, &manifolds, numeric);
  ceres::GradientChecker::ProbeResults results;
  checker.Probe(blocks.data(), 1e-6, &results);
  ASSERT_TRUE(results.return_value);
  ASSERT_EQ(results.local_jacobians.size(), blocks.size());
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    const auto& user = results.local_jacobians[k];
    const auto& num = results.local_numeric_jacobians[k];
    ASSERT_EQ(user.rows(), num.rows());
    ASSERT_EQ(user.cols(), num.cols());
    for (Eigen::Index r = 0; r < user.rows(); ++r) {
      for (Eigen::Index c = 0; c < user.cols(); ++c) {
        EXPECT_NEAR(user(r, c), num(r, c), 1e-6 * std::max(1.0, std::abs(num(r, c))))
            << "block " << k << " (" << r << ", " << c << ")";
      }
    }
  }
}

TEST(PlaneFromMoments, SquaredNormIsTheWeightedSumOverThePoints) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  std::vector<Eigen::Vector3d> pts;
  std::vector<double> w;
  for (int i = 0; i < 200; ++i) {
    pts.emplace_back(u(rng), u(rng), 0.1 * u(rng));
    w.push_back(0.5 + 0.25 * u(rng));
  }
  double W = 0;
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < pts.size(); ++i) {
    W += w[i];
    c += w[i] * pts[i];
  }
  c /= W;
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < pts.size(); ++i) {
    A += w[i] * (pts[i] - c) * (pts[i] - c).transpose();
  }
  const double sigma = 0.03;
  PlaneFromMoments f(A, c, W, sigma);
  for (int k = 0; k < 20; ++k) {
    std::array<double, 3> n{u(rng), u(rng), u(rng)};
    Eigen::Map<Eigen::Vector3d>(n.data()).normalize();
    const double d = u(rng);
    double res[4];
    ASSERT_TRUE(f(n.data(), &d, res));
    double direct = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const double h = Eigen::Map<Eigen::Vector3d>(n.data()).dot(pts[i]) - d;
      direct += w[i] * h * h / (sigma * sigma);
    }
    const double moments = res[0] * res[0] + res[1] * res[1] + res[2] * res[2] + res[3] * res[3];
    EXPECT_NEAR(moments, direct, 1e-9 * direct);
  }
  std::array<double, 3> n{0.1, 0.2, 0.97};
  Eigen::Map<Eigen::Vector3d>(n.data()).normalize();
  double d = 0.05;
  ceres::AutoDiffCostFunction<PlaneFromMoments, 4, 3, 1> cost(new PlaneFromMoments(A, c, W, sigma));
  expectGradientsMatch(cost, {n.data(), &d});
}

TEST(BeyondBounds, ZeroInsideAndWithThePlaneDistanceItIsEq5) {
  SurfaceParams p = tiltedSurface();
  const em::Rectangle r = p.toRectangle();
  const double sigma = 0.05;
  for (const Eigen::Vector3d& q :
       {Eigen::Vector3d(r.centre + 2.0 * r.axis_u + 0.1 * r.normal),
        Eigen::Vector3d(r.centre - 1.7 * r.axis_u + 1.4 * r.axisV() - 0.3 * r.normal),
        Eigen::Vector3d(r.centre + 0.2 * r.axisV() + 0.04 * r.normal)}) {
    BeyondBounds f(q, p.ref_centre, p.ref_axis, sigma);
    double res[2];
    ASSERT_TRUE(f(p.normal.data(), &p.offset, &p.rotation, p.bounds.data(), res));
    const double h = r.planeDistance(q);
    const double d2 = h * h + (res[0] * res[0] + res[1] * res[1]) * sigma * sigma;
    EXPECT_NEAR(d2, r.squaredDistance(q), 1e-12);
  }
}

TEST(BeyondBounds, GradientsMatchNumericOutside) {
  SurfaceParams p = tiltedSurface();
  const em::Rectangle r = p.toRectangle();
  // Off the plane, so that the frame's dependence on the normal shows.
  for (const Eigen::Vector3d& q :
       {Eigen::Vector3d(r.centre + 2.1 * r.axis_u - 1.3 * r.axisV() + 0.4 * r.normal),
        Eigen::Vector3d(r.centre - 1.9 * r.axis_u + 1.6 * r.axisV() - 0.7 * r.normal)}) {
    ceres::AutoDiffCostFunction<BeyondBounds, 2, 3, 1, 1, 4> cost(
        new BeyondBounds(q, p.ref_centre, p.ref_axis, 0.02));
    expectGradientsMatch(cost, {p.normal.data(), &p.offset, &p.rotation, p.bounds.data()});
  }
}

TEST(EdgeOnPlane, ResidualIsTheDistanceToTheOtherPlane) {
  // A wall y = 0 whose top edge (edge 2, v = v_max) is at z = 2.6; the
  // ceiling z = 2.7 (normal -z, offset -2.7): the edge is 10 cm below it.
  em::Rectangle wall;
  wall.normal = Eigen::Vector3d::UnitY();
  wall.centre = Eigen::Vector3d(2, 0, 1.3);
  wall.axis_u = -Eigen::Vector3d::UnitX();  // v = n x u = +z
  wall.half_u = 2.0;
  wall.half_v = 1.3;
  SurfaceParams a = SurfaceParams::fromRectangle(wall);
  std::array<double, 3> ceiling_n{0, 0, -1};
  double ceiling_d = -2.7;
  EdgeOnPlane f(2, {1.0, -1.0}, a.ref_centre, a.ref_axis, 0.002);
  double res[2];
  ASSERT_TRUE(f(a.normal.data(), &a.offset, &a.rotation, a.bounds.data(), ceiling_n.data(),
                &ceiling_d, res));
  EXPECT_NEAR(res[0], 0.1 / 0.002, 1e-9);
  EXPECT_NEAR(res[1], 0.1 / 0.002, 1e-9);
}

TEST(EdgeOnPlane, GradientsMatchNumeric) {
  SurfaceParams a = tiltedSurface();
  std::array<double, 3> nb{0.9, -0.1, 0.3};
  Eigen::Map<Eigen::Vector3d>(nb.data()).normalize();
  double db = 0.7;
  for (int edge = 0; edge < 4; ++edge) {
    ceres::AutoDiffCostFunction<EdgeOnPlane, 2, 3, 1, 1, 4, 3, 1> cost(
        new EdgeOnPlane(edge, {-0.3, 0.6}, a.ref_centre, a.ref_axis, 0.01));
    expectGradientsMatch(
        cost, {a.normal.data(), &a.offset, &a.rotation, a.bounds.data(), nb.data(), &db});
  }
}

TEST(ExtentPrior, ZeroAtTheFitAndLinearAway) {
  SurfaceParams p = tiltedSurface();
  ExtentPrior f(p, 0.05, 0.1);
  double res[5];
  ASSERT_TRUE(f(&p.rotation, p.bounds.data(), res));
  for (double r : res)
    EXPECT_NEAR(r, 0.0, 1e-12);
  std::array<double, 4> moved = p.bounds;
  moved[kVMax] += 0.1;
  double turned = p.rotation + 0.05;
  ASSERT_TRUE(f(&turned, moved.data(), res));
  EXPECT_NEAR(res[kVMax], 2.0, 1e-12);
  EXPECT_NEAR(res[4], 0.5, 1e-12);
  ceres::AutoDiffCostFunction<ExtentPrior, 5, 1, 4> cost(new ExtentPrior(p, 0.05, 0.1));
  expectGradientsMatch(cost, {&turned, moved.data()});
}

TEST(ManhattanPrior, OrthogonalAndParallelResiduals) {
  std::array<double, 3> a{1, 0, 0};
  std::array<double, 3> b{std::sin(0.01), std::cos(0.01), 0};  // 89.43 deg from a
  ManhattanPrior orthogonal(true, 0.001);
  double res[3];
  ASSERT_TRUE(orthogonal(a.data(), b.data(), res));
  EXPECT_NEAR(res[0], std::sin(0.01) / std::sin(0.001), 1e-9);
  std::array<double, 3> c{-std::cos(0.02), std::sin(0.02), 0};  // antiparallel, 1.1 deg off
  ManhattanPrior parallel(false, 0.001);
  ASSERT_TRUE(parallel(a.data(), c.data(), res));
  EXPECT_NEAR(std::hypot(res[0], res[1], res[2]), std::sin(0.02) / std::sin(0.001), 1e-9);
  ceres::AutoDiffCostFunction<ManhattanPrior, 3, 3, 3> o_cost(new ManhattanPrior(true, 0.01));
  expectGradientsMatch(o_cost, {a.data(), b.data()});
  ceres::AutoDiffCostFunction<ManhattanPrior, 3, 3, 3> p_cost(new ManhattanPrior(false, 0.01));
  expectGradientsMatch(p_cost, {a.data(), c.data()});
}

}  // namespace
}  // namespace pmap::refine
