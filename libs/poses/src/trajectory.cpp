#include "pmap/poses/trajectory.h"

#include <mrpt/poses/CPose3D.h>

#include <Eigen/Geometry>
#include <algorithm>

namespace pmap::poses {

bool Trajectory::append(double t, const mrpt::math::TPose3D& pose) {
  if (!poses_.empty()) {
    if (t < poses_.back().t) {
      return false;
    }
    if (t == poses_.back().t) {
      poses_.back().pose = pose;
      return true;
    }
  }
  poses_.push_back({t, pose});
  return true;
}

std::optional<mrpt::math::TPose3D> Trajectory::at(double t, double max_gap_s) const {
  if (poses_.empty() || t < poses_.front().t || t > poses_.back().t) {
    return std::nullopt;
  }
  const auto hi = std::lower_bound(poses_.begin(), poses_.end(), t,
                                   [](const TimedPose& p, double time) { return p.t < time; });
  if (hi->t == t) {
    return hi->pose;
  }
  const auto lo = hi - 1;
  if (hi->t - lo->t > max_gap_s) {
    return std::nullopt;
  }
  return interpolatePose(lo->pose, hi->pose, (t - lo->t) / (hi->t - lo->t));
}

mrpt::math::TPose3D interpolatePose(const mrpt::math::TPose3D& a, const mrpt::math::TPose3D& b,
                                    double s) {
  const mrpt::poses::CPose3D pa(a);
  const mrpt::poses::CPose3D pb(b);
  const Eigen::Quaterniond qa(pa.getRotationMatrix().asEigen());
  const Eigen::Quaterniond qb(pb.getRotationMatrix().asEigen());
  const Eigen::Matrix3d r = qa.slerp(s, qb).toRotationMatrix();
  mrpt::math::CMatrixDouble33 rot;
  rot.asEigen() = r;
  mrpt::poses::CPose3D out;
  out.setRotationMatrix(rot);
  out.x(a.x + s * (b.x - a.x));
  out.y(a.y + s * (b.y - a.y));
  out.z(a.z + s * (b.z - a.z));
  return out.asTPose();
}

}  // namespace pmap::poses
