#include "pmap/poses/pose_stage.h"

#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/system/datetime.h>

#include <cmath>

#include "pmap/common/error.h"
#include "pmap/common/text.h"

namespace pmap::poses {
namespace {

using mrpt::math::TPose3D;

// Seconds, NaN for a missing timestamp (zero or invalid: MRPT's demo logs
// carry actions with zero timestamps).
double secondsOf(mrpt::Clock::time_point t) {
  if (t == INVALID_TIMESTAMP || t.time_since_epoch().count() == 0) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return mrpt::Clock::toDouble(t);
}

TPose3D pose3(const mrpt::poses::CPose2D& p) {
  return TPose3D(p.x(), p.y(), 0.0, p.phi(), 0.0, 0.0);
}

bool same(const TPose3D& a, const TPose3D& b) {
  return a.x == b.x && a.y == b.y && a.z == b.z && a.yaw == b.yaw;
}

// The given poses that pass the gate.
Trajectory gated(const Trajectory& given, MotionGate& gate) {
  Trajectory out;
  for (const TimedPose& p : given.poses()) {
    if (const auto used = gate.absolute(p.t, p.pose)) {
      out.append(p.t, *used);
    }
  }
  return out;
}

MotionLimits withoutReset(MotionLimits limits) {
  limits.reset_after = 0;
  return limits;
}

}  // namespace

PoseStage::PoseStage(std::unique_ptr<IcpPoseTracker> tracker, MotionLimits limits,
                     LoopClosureOptions loops)
    : tracker_(std::move(tracker)),
      slam_(loops.enabled ? std::make_unique<LoopClosingStage>(loops, *tracker_) : nullptr),
      gate_(limits) {}

PoseStage::PoseStage(const Trajectory& given, MotionLimits limits)
    : gate_(withoutReset(limits)), given_(gated(given, gate_)) {}

PoseStats PoseStage::stats() const {
  PoseStats s = tracker_ ? tracker_->stats() : PoseStats{};
  s.actions_timed_by_frame = actions_timed_by_frame_;
  s.actions_without_time = actions_without_time_;
  return s;
}

const Trajectory& PoseStage::trajectory() const {
  if (slam_) {
    return slam_->trajectory();
  }
  return tracker_ ? tracker_->trajectory() : given_;
}

// A pose-laser scan: to ICP, then (with loop closure) to the pose graph.
void PoseStage::processPoseScan(const mrpt::obs::CObservation::Ptr& obs) {
  tracker_->processObservation(obs, false);
  if (slam_) {
    if (const auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obs)) {
      slam_->onScan(mrpt::Clock::toDouble(obs->timestamp), scan, odometry_);
    }
  }
}

// The odometry for the pose graph: the readings (observations-only format,
// absolute) or the increments (sf format) the gate passed, with the path
// they drove. A scan uses the last one before it (the logs seen write the
// reading of a scan's time just before it).
void PoseStage::odometryReading(const TPose3D& reading) {
  const Pose2 p{reading.x, reading.y, reading.yaw};
  const double path =
      odometry_ ? odometry_->path_m + std::hypot(p.x - odometry_->pose.x, p.y - odometry_->pose.y)
                : 0.0;
  odometry_ = OdometrySample{p, path};
}

void PoseStage::odometryIncrement(const mrpt::poses::CPose2D& step) {
  const OdometrySample last = odometry_.value_or(OdometrySample{});
  odometry_ = OdometrySample{compose(last.pose, {step.x(), step.y(), step.phi()}),
                             last.path_m + std::hypot(step.x(), step.y())};
}

void PoseStage::processOdometry(const mrpt::obs::CObservation::Ptr& obs) {
  const auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(obs);
  if (!odo) {
    return;
  }
  const TPose3D reading = pose3(odo->odometry);
  const auto used = gate_.absolute(secondsOf(obs->timestamp), reading);
  if (!used) {
    return;
  }
  odometryReading(*used);
  if (same(*used, reading)) {
    tracker_->processObservation(obs, true);
    return;
  }
  auto moved = std::make_shared<mrpt::obs::CObservationOdometry>(*odo);  // re-anchored
  moved->odometry = mrpt::poses::CPose2D(used->x, used->y, used->yaw);
  tracker_->processObservation(moved, true);
}

// An action whose odometry increment is implausible is dropped whole. An
// action without a timestamp (zero: MRPT's localization_demo.rawlog) takes
// its frame's time, `frame_t` (MRPT's ICP asserts on a missing one); with no
// time at all it is dropped and counted.
mrpt::obs::CActionCollection::Ptr PoseStage::gatedAction(
    const mrpt::obs::CActionCollection::Ptr& action, double frame_t) {
  if (!action) {
    return action;
  }
  auto out = std::make_shared<mrpt::obs::CActionCollection>();
  for (const auto& a : *action) {
    const auto* move = dynamic_cast<const mrpt::obs::CActionRobotMovement2D*>(a.get());
    if (move == nullptr) {
      out->insertPtr(a.get_ptr());
      continue;
    }
    double t = secondsOf(move->timestamp);
    if (!std::isfinite(t) && std::isfinite(frame_t)) {
      ++actions_timed_by_frame_;
      t = frame_t;
    }
    const double dt = t - last_action_t_;
    last_action_t_ = std::isfinite(t) ? t : last_action_t_;
    if (!std::isfinite(t)) {
      ++actions_without_time_;
      return nullptr;
    }
    // The increment MRPT's ICP composes: the mean of the movement's PDF.
    const mrpt::poses::CPose2D step =
        move->poseChange ? move->poseChange->getMeanVal() : move->rawOdometryIncrementReading;
    if (!gate_.increment(dt, pose3(step))) {
      return nullptr;
    }
    // Timed in place, not copied: actions deserialized from old rawlogs can
    // hold enum and bool fields MRPT left unset, which a copy would read.
    auto timed = std::dynamic_pointer_cast<mrpt::obs::CActionRobotMovement2D>(a.get_ptr());
    timed->timestamp = mrpt::Clock::fromDouble(t);
    out->insertPtr(timed);
  }
  // The increment MRPT's ICP takes (processActionObservation) is also the
  // pose graph's.
  if (const auto best = out->getBestMovementEstimation()) {
    odometryIncrement(best->poseChange ? best->poseChange->getMeanVal()
                                       : best->rawOdometryIncrementReading);
  }
  return out;
}

void PoseStage::processFrame(const input::InputStep& step) {
  std::vector<mrpt::obs::CObservation::Ptr> for_icp;
  double frame_t = std::numeric_limits<double>::quiet_NaN();
  for (const auto& item : step.observations) {
    if (item.roles.pose_laser || item.roles.odometry) {
      for_icp.push_back(item.obs);
      const double t = secondsOf(item.obs->timestamp);
      frame_t = std::isfinite(frame_t) ? std::max(frame_t, t) : t;
    }
  }
  const auto action = gatedAction(step.action, frame_t);
  if (!for_icp.empty() || action) {
    tracker_->processFrame(action, for_icp);
  }
  if (slam_) {
    for (const auto& item : step.observations) {
      const auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(item.obs);
      if (item.roles.pose_laser && scan) {
        slam_->onScan(frame_t, scan, odometry_);
      }
    }
  }
}

void PoseStage::finish() {
  if (slam_) {
    slam_->finish();
  }
}

void PoseStage::process(const input::InputStep& step, const std::string& file) {
  if (!tracker_) {
    return;
  }
  try {
    if (step.sensory_frame) {
      processFrame(step);
    } else {
      for (const auto& item : step.observations) {
        if (item.roles.odometry) {
          processOdometry(item.obs);
        } else if (item.roles.pose_laser) {
          processPoseScan(item.obs);
        }
      }
    }
    if (slam_) {
      slam_->sync();
    }
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(file + ": record " + std::to_string(step.record) + " at byte " +
                     std::to_string(step.offset) +
                     ": rejected by the ICP pose stage: " + oneLineError(e.what()));
  }
}

}  // namespace pmap::poses
