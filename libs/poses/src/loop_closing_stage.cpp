#include "pmap/poses/loop_closing_stage.h"

#include <mrpt/poses/CPose3D.h>

#include <cmath>

namespace pmap::poses {
namespace {

Pose2 pose2(const mrpt::math::TPose3D& p) {
  return {p.x, p.y, p.yaw};
}

bool samePose(const TimedPose& a, const TimedPose& b) {
  return a.t == b.t && a.pose.x == b.pose.x && a.pose.y == b.pose.y && a.pose.yaw == b.pose.yaw;
}

}  // namespace

bool isReturn(const mrpt::obs::CObservation2DRangeScan& scan, std::size_t i) {
  const double r = scan.getScanRange(i);
  return scan.getScanRangeValidity(i) && std::isfinite(r) && r > 0.0 && r < 0.999 * scan.maxRange;
}

std::vector<Eigen::Vector2d> scanPointsInRobotFrame(
    const mrpt::obs::CObservation2DRangeScan& scan) {
  std::vector<Eigen::Vector2d> out;
  const mrpt::poses::CPose3D& sensor = scan.sensorPose;
  for (std::size_t i = 0; i < scan.getScanSize(); ++i) {
    if (!isReturn(scan, i)) {
      continue;
    }
    const double r = scan.getScanRange(i);
    const double a = scan.getScanAngle(i);
    const mrpt::math::TPoint3D p =
        sensor.composePoint(mrpt::math::TPoint3D(r * std::cos(a), r * std::sin(a), 0.0));
    if (std::isfinite(p.x) && std::isfinite(p.y)) {
      out.emplace_back(p.x, p.y);
    }
  }
  return out;
}

LoopClosingStage::LoopClosingStage(LoopClosureOptions options, IcpPoseTracker& tracker)
    : tracker_(tracker), back_end_(options) {}

TimedPose LoopClosingStage::correctedSample(std::size_t i) const {
  const TimedPose& p = tracker_.trajectory().poses()[i];
  if (back_end_.empty()) {
    return p;
  }
  const Pose2 c = back_end_.corrected(sample_anchor_[i], pose2(p.pose));
  return {p.t, mrpt::math::TPose3D(c.x, c.y, p.pose.z, c.theta, p.pose.pitch, p.pose.roll)};
}

void LoopClosingStage::sync() {
  const auto& front = tracker_.trajectory().poses();
  std::size_t from = sample_anchor_.size();
  // The tracker replaces its last sample when a later one has the same time.
  if (from > 0 && from <= front.size() && !samePose(front[from - 1], corrected_front_last_)) {
    --from;
  }
  const ScanAnchor anchor = back_end_.anchor();
  sample_anchor_.resize(front.size(), anchor);
  for (std::size_t i = from; i < front.size(); ++i) {
    sample_anchor_[i] = anchor;
    const TimedPose c = correctedSample(i);
    corrected_.append(c.t, c.pose);
  }
  if (!front.empty()) {
    corrected_front_last_ = front.back();
  }
}

void LoopClosingStage::onScan(double t, const mrpt::obs::CObservation2DRangeScan::Ptr& scan,
                              const std::optional<OdometrySample>& odometry) {
  sync();
  const ScanAnchor before = back_end_.anchor();
  const bool closed =
      back_end_.addScan(t, pose2(tracker_.currentPose()), scanPointsInRobotFrame(*scan), odometry);
  // A new keyframe or a refined scan: this scan's sample is the new anchor.
  const ScanAnchor& after = back_end_.anchor();
  if (after.scan != before.scan && !sample_anchor_.empty()) {
    sample_anchor_.back() = after;
    const TimedPose c = correctedSample(sample_anchor_.size() - 1);
    corrected_.append(c.t, c.pose);
  }
  if (closed) {
    recomputeAll();
  }
  updateFrontMap(closed);
}

// The front end's map (front_map_radius_m > 0): after a closure, rebuilt
// from the keyframes within the radius of the robot's corrected pose c,
// placed by the graph and moved into the front end's frame by f (+) c^-1 (f:
// the front end's pose now), so the robot's own front-end pose stays where
// it is; otherwise MRPT's own map, trimmed to the radius every quarter of it
// travelled (doc/poses.md, "The front end's map").
void LoopClosingStage::updateFrontMap(bool closed) {
  const LoopClosureOptions& o = back_end_.options();
  if (!(o.front_map_radius_m > 0.0) || back_end_.empty()) {
    return;
  }
  const Pose2 f = pose2(tracker_.currentPose());
  if (!closed && last_update_ &&
      std::hypot(f.x - last_update_->x, f.y - last_update_->y) < 0.25 * o.front_map_radius_m) {
    return;
  }
  last_update_ = f;
  if (!closed) {
    tracker_.clipMap(f.x, f.y, o.front_map_radius_m);
    return;
  }
  const Pose2 c = back_end_.corrected(back_end_.anchor(), f);
  const Pose2 frame = compose(c, inverse(f));  // the front end's frame, in the graph's
  tracker_.replaceMap(back_end_.localMap(c, o.front_map_radius_m, frame, o.front_map_spacing_m));
  ++front_map_rebuilds_;
}

void LoopClosingStage::finish() {
  sync();
  if (back_end_.finish()) {
    recomputeAll();
  }
}

void LoopClosingStage::recomputeAll() {
  ++corrections_;
  corrected_ = Trajectory();
  for (std::size_t i = 0; i < sample_anchor_.size(); ++i) {
    const TimedPose c = correctedSample(i);
    corrected_.append(c.t, c.pose);
  }
}

}  // namespace pmap::poses
