#include "pmap/points/scan_placer.h"

#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace pmap::points {

void ScanPlacer::place(const input::StructureScan& scan, const mrpt::math::TPose3D& pose) {
  const std::size_t record = map_.addScan(scan, pose);
  ++stats_.placed;
  if (on_placed_) {
    on_placed_(scan, record);
  }
}

void ScanPlacer::drain(const poses::Trajectory& trajectory, bool final_all) {
  if (trajectory.empty()) {
    return;
  }
  const auto& samples = trajectory.poses();
  // Latest time up to which interpolation uses final samples only.
  double final_until = trajectory.lastTime();
  if (!final_all) {
    if (samples.size() < 2) {
      return;
    }
    final_until = samples[samples.size() - 2].t;
  }
  while (!pending_.empty() && pending_.front().timestamp <= final_until) {
    const auto pose = trajectory.at(pending_.front().timestamp, max_gap_s_);
    if (pose) {
      place(pending_.front(), *pose);
    } else {
      ++stats_.without_pose;
    }
    pending_.pop_front();
  }
  if (final_all) {
    stats_.without_pose += pending_.size();  // after the last pose
    pending_.clear();
  }
}

namespace {

bool samePlace(const mrpt::math::TPose3D& a, const mrpt::math::TPose3D& b) {
  constexpr double kShiftM = 1e-4;
  constexpr double kTurnRad = 1e-5;
  return std::abs(a.x - b.x) <= kShiftM && std::abs(a.y - b.y) <= kShiftM &&
         std::abs(a.z - b.z) <= kShiftM &&
         std::abs(mrpt::math::wrapToPi(a.yaw - b.yaw)) <= kTurnRad &&
         std::abs(mrpt::math::wrapToPi(a.pitch - b.pitch)) <= kTurnRad &&
         std::abs(mrpt::math::wrapToPi(a.roll - b.roll)) <= kTurnRad;
}

}  // namespace

std::vector<std::size_t> ScanPlacer::follow(const poses::Trajectory& trajectory) {
  std::vector<std::size_t> moved;
  for (std::size_t i = 0; i < map_.scans().size(); ++i) {
    const ScanRecord& s = map_.scans()[i];
    const auto pose = trajectory.at(s.timestamp, max_gap_s_);
    if (pose && !samePlace(*pose, s.robot_pose)) {
      map_.moveScan(i, *pose);
      moved.push_back(i);
    }
  }
  return moved;
}

void ScanPlacer::placeAllAt(const mrpt::math::TPose3D& pose) {
  for (const auto& scan : pending_) {
    place(scan, pose);
  }
  pending_.clear();
}

}  // namespace pmap::points
