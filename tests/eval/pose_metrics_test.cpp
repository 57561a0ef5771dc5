#include "pmap/eval/pose_metrics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pmap::eval {
namespace {
using mrpt::math::TPose3D;

TEST(PoseMetrics, RigidAlignmentRecoversAKnownMotion) {
  const Rigid2D truth{0.7, {3.0, -1.0}};
  std::vector<Eigen::Vector2d> a;
  std::vector<Eigen::Vector2d> b;
  for (int i = 0; i < 10; ++i) {
    a.emplace_back(i * 0.5, std::sin(i));
    b.push_back(truth.apply({a.back().x(), a.back().y(), 0}).head<2>());
  }
  const Rigid2D r = alignRigid2D(a, b);
  EXPECT_NEAR(r.yaw, 0.7, 1e-12);
  EXPECT_NEAR(r.t.x(), 3.0, 1e-12);
  EXPECT_NEAR(r.t.y(), -1.0, 1e-12);
}

TEST(PoseMetrics, AteIsZeroForARigidlyMovedCopyAndMeasuresNoise) {
  poses::Trajectory gt;
  poses::Trajectory est;
  const Rigid2D move{-1.2, {5, 2}};
  for (int i = 0; i < 50; ++i) {
    const double t = i * 0.2;
    const Eigen::Vector3d p(i * 0.1, 0.3 * std::sin(i * 0.2), 0);
    const Eigen::Vector3d q = move.apply(p);
    gt.append(t, TPose3D(q.x(), q.y(), 0, 0.1 * i - 1.2, 0, 0));
    const double noise = (i % 2 == 0) ? 0.01 : -0.01;
    est.append(t, TPose3D(p.x(), p.y() + noise, 0, 0.1 * i, 0, 0));
  }
  const PoseErrors e = comparePoses(est, gt);
  EXPECT_EQ(e.matched, 50u);
  EXPECT_NEAR(e.ate_m, 0.01, 1e-3);
  EXPECT_NEAR(e.alignment.yaw, -1.2, 1e-2);
  EXPECT_LT(e.yaw_rms_deg, 1.0);
  EXPECT_NEAR(e.ate_first_pose_m, 0.01, 0.01);
}

TEST(PoseMetrics, PosesOutsideTheGroundTruthAreSkipped) {
  poses::Trajectory gt;
  gt.append(1, TPose3D());
  gt.append(2, TPose3D(1, 0, 0, 0, 0, 0));
  poses::Trajectory est;
  est.append(0.5, TPose3D());
  est.append(1.5, TPose3D(0.5, 0, 0, 0, 0, 0));
  est.append(2.5, TPose3D(9, 0, 0, 0, 0, 0));
  EXPECT_EQ(comparePoses(est, gt).matched, 1u);
}

}  // namespace
}  // namespace pmap::eval
