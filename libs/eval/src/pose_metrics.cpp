#include "pmap/eval/pose_metrics.h"

#include <mrpt/core/bits_math.h>
#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace pmap::eval {

Eigen::Vector3d Rigid2D::apply(const Eigen::Vector3d& p) const {
  const double c = std::cos(yaw);
  const double s = std::sin(yaw);
  return {c * p.x() - s * p.y() + t.x(), s * p.x() + c * p.y() + t.y(), p.z()};
}

Eigen::Vector3d Rigid2D::rotate(const Eigen::Vector3d& v) const {
  const double c = std::cos(yaw);
  const double s = std::sin(yaw);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y(), v.z()};
}

Rigid2D alignRigid2D(const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b) {
  Rigid2D r;
  if (a.empty() || a.size() != b.size()) {
    return r;
  }
  Eigen::Vector2d ca = Eigen::Vector2d::Zero();
  Eigen::Vector2d cb = Eigen::Vector2d::Zero();
  for (size_t i = 0; i < a.size(); ++i) {
    ca += a[i];
    cb += b[i];
  }
  ca /= static_cast<double>(a.size());
  cb /= static_cast<double>(b.size());
  // Optimal rotation angle: atan2(sum cross, sum dot) of the centred pairs.
  double sdot = 0;
  double scross = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    const Eigen::Vector2d u = a[i] - ca;
    const Eigen::Vector2d v = b[i] - cb;
    sdot += u.dot(v);
    scross += u.x() * v.y() - u.y() * v.x();
  }
  r.yaw = (sdot == 0 && scross == 0) ? 0.0 : std::atan2(scross, sdot);
  const double c = std::cos(r.yaw);
  const double s = std::sin(r.yaw);
  r.t = cb - Eigen::Vector2d(c * ca.x() - s * ca.y(), s * ca.x() + c * ca.y());
  return r;
}

PoseErrors comparePoses(const poses::Trajectory& estimated, const poses::Trajectory& truth) {
  PoseErrors e;
  std::vector<Eigen::Vector2d> est;
  std::vector<Eigen::Vector2d> gt;
  std::vector<double> est_yaw;
  std::vector<double> gt_yaw;
  for (const auto& p : estimated.poses()) {
    const auto g = truth.at(p.t, 1e9);
    if (!g) {
      continue;
    }
    est.emplace_back(p.pose.x, p.pose.y);
    gt.emplace_back(g->x, g->y);
    est_yaw.push_back(p.pose.yaw);
    gt_yaw.push_back(g->yaw);
  }
  e.matched = est.size();
  if (est.empty()) {
    return e;
  }
  e.alignment = alignRigid2D(est, gt);
  double sum2 = 0;
  double yaw2 = 0;
  for (size_t i = 0; i < est.size(); ++i) {
    const Eigen::Vector3d q = e.alignment.apply({est[i].x(), est[i].y(), 0});
    const double d = (q.head<2>() - gt[i]).norm();
    sum2 += d * d;
    e.max_error_m = std::max(e.max_error_m, d);
    const double dy = mrpt::math::wrapToPi(e.alignment.applyYaw(est_yaw[i]) - gt_yaw[i]);
    yaw2 += dy * dy;
    if (i + 1 == est.size()) {
      e.final_error_m = d;
    }
  }
  e.ate_m = std::sqrt(sum2 / static_cast<double>(est.size()));
  e.yaw_rms_deg = mrpt::RAD2DEG(std::sqrt(yaw2 / static_cast<double>(est.size())));
  // Frames tied at the first pose: rotate/translate so the first poses coincide.
  Rigid2D first;
  first.yaw = gt_yaw[0] - est_yaw[0];
  const Eigen::Vector3d r0 = Rigid2D{first.yaw, {0, 0}}.apply({est[0].x(), est[0].y(), 0});
  first.t = gt[0] - r0.head<2>();
  double sum_first = 0;
  for (size_t i = 0; i < est.size(); ++i) {
    const double d = (first.apply({est[i].x(), est[i].y(), 0}).head<2>() - gt[i]).norm();
    sum_first += d * d;
  }
  e.ate_first_pose_m = std::sqrt(sum_first / static_cast<double>(est.size()));
  return e;
}

}  // namespace pmap::eval
