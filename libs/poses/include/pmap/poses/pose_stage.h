// Feeds the pose-relevant observations of each input step to the ICP
// tracker: odometry (readings or sf-format actions) and pose-laser scans,
// nothing else. With given poses (--poses) the trajectory is fixed and steps
// are ignored. Odometry passes a MotionGate first: physically implausible
// readings and increments are dropped and counted (motion_gate.h).
#pragma once

#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "pmap/input/observation_source.h"
#include "pmap/poses/icp_pose_tracker.h"
#include "pmap/poses/loop_closing_stage.h"
#include "pmap/poses/motion_gate.h"
#include "pmap/poses/trajectory.h"

namespace pmap::poses {

class PoseStage {
 public:
  /// ICP poses; odometry is gated by `limits`; with loop closure enabled the
  /// trajectory is the pose graph's (loop_closing_stage.h).
  PoseStage(std::unique_ptr<IcpPoseTracker> tracker, MotionLimits limits,
            LoopClosureOptions loops = disabledLoops());
  /// Given poses, gated by `limits` (no re-anchoring: a given trajectory is
  /// not an odometry counter).
  PoseStage(const Trajectory& given, MotionLimits limits);

  /// Throws InputError (naming the record) when MRPT rejects an observation.
  void process(const input::InputStep& step, const std::string& file);
  /// After the last step: with loop closure, a search still running on its
  /// worker is applied (the trajectory may change once more).
  void finish();

  const Trajectory& trajectory() const;
  /// True when every sample of trajectory() is final up to its last one
  /// (given poses); otherwise the last sample may still be replaced.
  bool fixed() const { return !tracker_; }
  const char* source() const { return tracker_ ? "icp" : "file"; }
  PoseStats stats() const;
  /// What the motion gate dropped (odometry, or the given poses).
  const MotionGate& gate() const { return gate_; }
  /// The loop-closing back end; null without loop closure.
  const LoopClosingBackEnd* loops() const { return slam_ ? &slam_->backEnd() : nullptr; }
  /// How many times a loop closure rewrote the past trajectory (0 without
  /// loop closure): scans placed before then must follow (ScanPlacer::follow).
  std::size_t corrections() const { return slam_ ? slam_->corrections() : 0; }
  /// How many times the front end's map was rebuilt from the pose graph.
  std::size_t frontMapRebuilds() const { return slam_ ? slam_->frontMapRebuilds() : 0; }

  static LoopClosureOptions disabledLoops() {
    LoopClosureOptions o;
    o.enabled = false;
    return o;
  }

 private:
  void processFrame(const input::InputStep& step);
  void processOdometry(const mrpt::obs::CObservation::Ptr& obs);
  void processPoseScan(const mrpt::obs::CObservation::Ptr& obs);
  mrpt::obs::CActionCollection::Ptr gatedAction(const mrpt::obs::CActionCollection::Ptr& action,
                                                double frame_t);
  void odometryReading(const mrpt::math::TPose3D& reading);
  void odometryIncrement(const mrpt::poses::CPose2D& step);

  std::unique_ptr<IcpPoseTracker> tracker_;
  std::unique_ptr<LoopClosingStage> slam_;
  MotionGate gate_;
  Trajectory given_;
  double last_action_t_ = std::numeric_limits<double>::quiet_NaN();
  std::size_t actions_timed_by_frame_ = 0;
  std::size_t actions_without_time_ = 0;
  /// The wheel odometry as the gate passed it: the last reading (or the
  /// sf-format increments composed) and the path driven, for the pose
  /// graph's motion prior.
  std::optional<OdometrySample> odometry_;
};

}  // namespace pmap::poses
