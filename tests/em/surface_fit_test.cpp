#include "pmap/em/surface_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "em_test_worlds.h"

namespace pmap::em {
namespace {

using testing::allIndices;

// Points on a rotated rectangle (2 hu x 2 hv) of the plane through `c`.
std::vector<Eigen::Vector3d> rectanglePoints(const Eigen::Isometry3d& T, double hu, double hv,
                                             int n, double noise, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> g(0.0, noise);
  std::vector<Eigen::Vector3d> pts;
  for (const auto& [a, b] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
    pts.push_back(T * Eigen::Vector3d(a * hu, b * hv, 0.0));
  }
  for (int k = 4; k < n; ++k) {
    pts.push_back(T * Eigen::Vector3d(hu * u(rng), hv * u(rng), g(rng)));
  }
  return pts;
}

PlaneMoments momentsOf(const std::vector<Eigen::Vector3d>& pts, const Eigen::Vector3d& ref) {
  PlaneMoments m;
  m.reference = ref;
  for (const auto& p : pts) {
    m.add(p, 1.0);
  }
  return m;
}

TEST(PlaneFromMoments, RecoversExactPlanesAnywhere) {
  std::mt19937_64 rng(1);
  for (const double reach : {1.0, 1e3, 1e5}) {
    for (int t = 0; t < 10; ++t) {
      const Eigen::Isometry3d T = testing::randomMotion(rng, reach);
      const auto pts = rectanglePoints(T, 2.0, 0.5, 200, 0.0, rng);
      const Eigen::Vector3d n = T.linear().col(2);
      Rectangle r;
      ASSERT_EQ(planeFromMoments(momentsOf(pts, pts[0]), n, r), FitStatus::kOk);
      EXPECT_NEAR(r.normal.norm(), 1.0, 1e-15);
      EXPECT_GT(r.normal.dot(n), 1.0 - 1e-12);
      EXPECT_NEAR(r.offset, n.dot(T.translation()), 1e-9 * std::max(1.0, reach));
      EXPECT_NEAR(r.planeDistance(r.centre), 0.0, 1e-9 * std::max(1.0, reach));
      EXPECT_NEAR(r.axis_u.dot(r.normal), 0.0, 1e-12);
    }
  }
}

TEST(PlaneFromMoments, FollowsThePreviousNormalsSide) {
  std::mt19937_64 rng(2);
  const auto pts = rectanglePoints(Eigen::Isometry3d::Identity(), 1, 1, 50, 0.0, rng);
  Rectangle r;
  ASSERT_EQ(planeFromMoments(momentsOf(pts, {0, 0, 0}), {0.1, 0, -1}, r), FitStatus::kOk);
  EXPECT_TRUE(r.normal.isApprox(-Eigen::Vector3d::UnitZ()));
  ASSERT_EQ(planeFromMoments(momentsOf(pts, {0, 0, 0}), {0.1, 0, 1}, r), FitStatus::kOk);
  EXPECT_TRUE(r.normal.isApprox(Eigen::Vector3d::UnitZ()));
}

TEST(PlaneFromMoments, WeightsSelectThePoints) {
  // Two planes; with zero weight on the second, the first is found exactly.
  std::mt19937_64 rng(3);
  const auto a = rectanglePoints(Eigen::Isometry3d::Identity(), 1, 1, 100, 0.0, rng);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const auto b = rectanglePoints(T, 1, 1, 100, 0.0, rng);
  PlaneMoments m;
  for (const auto& p : a)
    m.add(p, 0.5);
  for (const auto& p : b)
    m.add(p, 0.0);
  Rectangle r;
  ASSERT_EQ(planeFromMoments(m, {0, 0, 1}, r), FitStatus::kOk);
  EXPECT_GT(r.normal.z(), 1.0 - 1e-12);
  EXPECT_DOUBLE_EQ(m.weight, 50.0);
}

TEST(PlaneFromMoments, MergeEqualsAddingEverything) {
  std::mt19937_64 rng(4);
  const auto pts = rectanglePoints(testing::randomMotion(rng, 5), 1, 2, 100, 0.01, rng);
  PlaneMoments whole, first, second;
  whole.reference = first.reference = second.reference = pts[3];
  for (std::size_t i = 0; i < pts.size(); ++i) {
    whole.add(pts[i], 0.3);
    (i < 40 ? first : second).add(pts[i], 0.3);
  }
  first.merge(second);
  EXPECT_NEAR(first.weight, whole.weight, 1e-12);
  EXPECT_TRUE(first.sum.isApprox(whole.sum, 1e-12));
  EXPECT_TRUE(first.sum_sq.isApprox(whole.sum_sq, 1e-12));
}

TEST(PlaneFromMoments, RejectsEmptyLinesAndPoints) {
  Rectangle r;
  const Rectangle before = r;
  EXPECT_EQ(planeFromMoments(PlaneMoments{}, {0, 0, 1}, r), FitStatus::kTooFewPoints);
  PlaneMoments zero;
  zero.add({1, 2, 3}, 0.0);
  EXPECT_EQ(planeFromMoments(zero, {0, 0, 1}, r), FitStatus::kTooFewPoints);
  std::vector<Eigen::Vector3d> line, point(20, Eigen::Vector3d(1, 2, 3)), far_line;
  for (int k = 0; k < 20; ++k) {
    line.push_back(Eigen::Vector3d(1, 2, 3) + k * Eigen::Vector3d(0.3, -0.1, 0.2));
    far_line.push_back(line.back() + Eigen::Vector3d(1e5, 1e5, 0));
  }
  EXPECT_EQ(planeFromMoments(momentsOf(line, line[0]), {0, 0, 1}, r), FitStatus::kDegenerate);
  EXPECT_EQ(planeFromMoments(momentsOf(point, point[0]), {0, 0, 1}, r), FitStatus::kDegenerate);
  EXPECT_EQ(planeFromMoments(momentsOf(far_line, far_line[0]), {0, 0, 1}, r),
            FitStatus::kDegenerate);
  EXPECT_EQ(r.normal, before.normal);  // untouched on failure
  EXPECT_EQ(r.centre, before.centre);
}

TEST(FitRectangle, RecoversARotatedRectangleAndKeepsThePlane) {
  std::mt19937_64 rng(5);
  for (int t = 0; t < 10; ++t) {
    const Eigen::Isometry3d T = testing::randomMotion(rng, 50.0);
    const auto pts = rectanglePoints(T, 1.5, 0.4, 300, 0.0, rng);
    Rectangle r;
    r.normal = T.linear().col(2);
    r.centre = T * Eigen::Vector3d(0.3, 0.2, 0.0);  // somewhere on the plane
    r.offset = r.normal.dot(r.centre);
    r.axis_u = r.normal.unitOrthogonal();
    const Rectangle plane = r;
    ASSERT_EQ(fitRectangle(pts, allIndices(pts.size()), r), FitStatus::kOk);
    EXPECT_EQ(r.normal, plane.normal);
    EXPECT_EQ(r.offset, plane.offset);
    EXPECT_NEAR(r.area(), 4 * 1.5 * 0.4, 1e-9);
    EXPECT_NEAR(std::max(r.half_u, r.half_v), 1.5, 1e-9);
    EXPECT_TRUE(r.centre.isApprox(T.translation(), 1e-9));
    EXPECT_NEAR(
        std::abs(r.axis_u.dot(T.linear().col(std::max(r.half_u, r.half_v) == r.half_u ? 0 : 1))),
        1.0, 1e-9);
    for (const auto& p : pts) {
      EXPECT_LT(r.squaredDistance(p), 1e-18);
    }
  }
}

TEST(FitRectangle, FewerThanThreeMembersAreTooFew) {
  const std::vector<Eigen::Vector3d> pts = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  Rectangle r;
  EXPECT_EQ(fitRectangle(pts, {}, r), FitStatus::kTooFewPoints);
  EXPECT_EQ(fitRectangle(pts, {0, 1}, r), FitStatus::kTooFewPoints);
  EXPECT_EQ(fitSurface(pts, {0, 1}, r), FitStatus::kTooFewPoints);
  EXPECT_EQ(fitRectangle(pts, {0, 1, 2}, r), FitStatus::kOk);
  EXPECT_NEAR(r.area(), 1.0, 1e-12);  // a right isosceles triangle: 1 x 1 either way
}

TEST(FitSurface, NoisyPlaneAndDegenerateSets) {
  std::mt19937_64 rng(6);
  const Eigen::Isometry3d T = testing::randomMotion(rng, 1e5);
  const auto pts = rectanglePoints(T, 2, 1, 2000, 0.02, rng);
  Rectangle r;
  ASSERT_EQ(fitSurface(pts, allIndices(pts.size()), r), FitStatus::kOk);
  EXPECT_LT(testing::lineAngleDeg(r.normal, T.linear().col(2)), 0.2);
  EXPECT_NEAR(std::abs(r.planeDistance(T.translation())), 0.0, 0.005);
  const std::vector<Eigen::Vector3d> same(10, Eigen::Vector3d(4, 5, 6));
  EXPECT_EQ(fitSurface(same, allIndices(10), r), FitStatus::kDegenerate);
}

// MRPT's getRegressionPlane rejects a perfectly flat 1 mm square as
// "aligned" (ROBUSTNESS.md); eigenvalue ratios do not depend on the scale.
TEST(FitSurface, AFlatOneMillimetreSquareIsATinyButValidPatch) {
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i < 10; ++i) {
    for (int j = 0; j < 10; ++j) {
      pts.emplace_back(1e-4 * i, 1e-4 * j, 0.0);
    }
  }
  Rectangle r;
  ASSERT_EQ(fitSurface(pts, allIndices(pts.size()), r), FitStatus::kOk);
  EXPECT_NEAR(std::abs(r.normal.z()), 1.0, 1e-12);
  EXPECT_NEAR(r.area(), 0.9e-3 * 0.9e-3, 1e-12);
}

TEST(CoherentMembers, DropsMembersWithFewSameCauseNeighbours) {
  // A 1 x 8 row: members 0..6 of surface 0, point 7 of surface 1; point 3 is
  // labelled 0 but both its neighbours are 1.
  testing::Cloud c;
  for (int k = 0; k < 8; ++k) {
    c.points.emplace_back(k, 0, 0);
    c.keys.push_back({0, 0, k});
  }
  const Neighbours n = c.neighbours();
  const std::vector<std::int32_t> best = {0, 0, 1, 0, 1, 0, 0, 1};
  EXPECT_EQ(coherentMembers({0, 1, 3, 5, 6}, n, best, 1), (std::vector<std::int32_t>{0, 1, 5, 6}));
  // min_same = 2 leaves nobody in a 1-wide row: all members come back.
  EXPECT_EQ(coherentMembers({0, 1, 3, 5, 6}, n, best, 2),
            (std::vector<std::int32_t>{0, 1, 3, 5, 6}));
  EXPECT_TRUE(coherentMembers({}, n, best, 1).empty());
}

TEST(HardMembers, GroupsPointsByMostLikelyCause) {
  Responsibilities r;
  r.best = {1, -1, 0, 1, -1, 1};
  r.outlier.resize(6);
  const auto m = hardMembers(r, 3);
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m[0], (std::vector<std::int32_t>{2}));
  EXPECT_EQ(m[1], (std::vector<std::int32_t>{0, 3, 5}));
  EXPECT_TRUE(m[2].empty());
}

// Two noisy walls and an empty surface; one M-step from perturbed planes.
struct MStepScene {
  testing::Cloud cloud;
  std::vector<Surface> surfaces;
  MStepScene() {
    std::mt19937_64 rng(7);
    testing::addPlane(cloud, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 4.0, 2.0, 0.05, 0.01, rng, 0);
    testing::addPlane(cloud, {0, 3, 0}, {1, 0, 0}, {0, 0, 1}, 4.0, 2.0, 0.05, 0.01, rng, 1);
    for (const double y : {0.02, 2.97, 50.0}) {
      Surface s;
      s.rect.normal = Eigen::Vector3d(0.02, 1, 0.01).normalized();
      s.rect.centre = {2, y, 1};
      s.rect.offset = s.rect.normal.dot(s.rect.centre);
      s.rect.axis_u = {1, 0, 0};
      s.rect.reproject();
      s.rect.half_u = 1.5;
      s.rect.half_v = 0.8;
      surfaces.push_back(s);
    }
  }
  Responsibilities expect(int threads) const {
    const MeasurementModel m(0.02, 30.0);
    Responsibilities r;
    computeResponsibilities(cloud.points, surfaces,
                            RectangleIndex(surfaces, m.cutoffDistance(1e-6)), m, 1e-6, threads, r);
    return r;
  }
};

TEST(MaximizeSurfaces, FitsPlanesAndRectanglesWithUnitNormals) {
  MStepScene s;
  const Rectangle idle = s.surfaces[2].rect;
  // The rectangles creep outwards by about the outlier distance per
  // iteration (hard members within the band); 20 iterations cover the walls.
  for (int it = 0; it < 20; ++it) {
    const Responsibilities r = s.expect(1);
    maximizeSurfaces(s.cloud.points, s.cloud.neighbours(), r, 1, s.surfaces);
    for (const Surface& sf : s.surfaces) {
      EXPECT_NEAR(sf.rect.normal.norm(), 1.0, 1e-14);
      EXPECT_NEAR(sf.rect.axis_u.norm(), 1.0, 1e-14);
      EXPECT_NEAR(sf.rect.axis_u.dot(sf.rect.normal), 0.0, 1e-14);
    }
  }
  EXPECT_LT(testing::lineAngleDeg(s.surfaces[0].rect.normal, Eigen::Vector3d::UnitY()), 0.1);
  EXPECT_NEAR(s.surfaces[0].rect.planeDistance({0, 0, 0}), 0.0, 0.003);
  EXPECT_NEAR(s.surfaces[1].rect.planeDistance({0, 3, 0}), 0.0, 0.003);
  EXPECT_NEAR(s.surfaces[0].rect.area(), 8.0, 0.3);  // grown to the whole wall
  EXPECT_EQ(s.surfaces[0].support + s.surfaces[1].support,
            static_cast<std::int32_t>(s.cloud.points.size()));
  // The surface without points keeps its geometry and has no support.
  EXPECT_EQ(s.surfaces[2].support, 0);
  EXPECT_EQ(s.surfaces[2].rect.centre, idle.centre);
  EXPECT_EQ(s.surfaces[2].rect.normal, idle.normal);
}

TEST(MaximizeSurfaces, UnboundedPlanesKeepTheirExtentsAndThreadsDoNotMatter) {
  MStepScene a, b;
  for (auto* s : {&a, &b}) {
    for (Surface& sf : s->surfaces) {
      sf.rect.bounded = false;
    }
  }
  maximizeSurfaces(a.cloud.points, a.cloud.neighbours(), a.expect(1), 1, a.surfaces);
  maximizeSurfaces(b.cloud.points, b.cloud.neighbours(), b.expect(4), 4, b.surfaces);
  for (std::size_t j = 0; j < a.surfaces.size(); ++j) {
    EXPECT_EQ(a.surfaces[j].rect.normal, b.surfaces[j].rect.normal);
    EXPECT_EQ(a.surfaces[j].rect.offset, b.surfaces[j].rect.offset);
    EXPECT_EQ(a.surfaces[j].rect.half_u, 1.5);
    EXPECT_EQ(a.surfaces[j].rect.half_v, 0.8);
  }
  EXPECT_LT(testing::lineAngleDeg(a.surfaces[0].rect.normal, Eigen::Vector3d::UnitY()), 0.1);
}

}  // namespace
}  // namespace pmap::em
