// Loop closure around the ICP front end (doc/poses.md, "Loop closure"): the
// front end (MRPT's CMetricMapBuilderICP) runs as without loop closure, in
// its own drifting frame; every pose-laser scan goes to the pose graph back
// end (loop_closure.h), and the trajectory handed on is the corrected one:
// each front-end pose follows the newest anchor at its time (ScanAnchor:
// the newest keyframe or the last scan refined after it),
//   corrected = keyframe's optimised pose (+) anchor's refined pose in the
//               keyframe's frame (+) (anchor's front pose^-1 (+) front pose).
// With front_map_radius_m > 0 the front end's point map is rebuilt after
// every closure from the keyframes near the robot, placed by the optimised
// graph and seen from the front end's current pose (the map around the
// robot is consistent with the corrected poses, and the front end's pose
// does not jump: rebuilding it in the graph's frame instead made the ICP
// snap to the moved map, and the snap entered the next edges as motion that
// never happened); between closures it is MRPT's own map, trimmed to the
// radius. With 0 the front end keeps MRPT's global map.
#pragma once

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <vector>

#include "pmap/poses/icp_pose_tracker.h"
#include "pmap/poses/loop_closure.h"
#include "pmap/poses/trajectory.h"

namespace pmap::poses {

/// Whether reading i of a 2D scan is a return: valid, finite, positive and
/// short of the maximum range (CARMEN logs flag max-range readings valid).
bool isReturn(const mrpt::obs::CObservation2DRangeScan& scan, std::size_t i);

/// A 2D scan's returns (isReturn) in the robot frame (x, y), through its
/// sensor pose.
std::vector<Eigen::Vector2d> scanPointsInRobotFrame(const mrpt::obs::CObservation2DRangeScan& scan);

class LoopClosingStage {
 public:
  LoopClosingStage(LoopClosureOptions options, IcpPoseTracker& tracker);

  /// After the tracker took the pose-laser scan `scan` at time `t`; the
  /// wheel odometry's last reading then (none: the log has no odometry).
  void onScan(double t, const mrpt::obs::CObservation2DRangeScan::Ptr& scan,
              const std::optional<OdometrySample>& odometry = std::nullopt);
  /// After every input step: the corrected trajectory follows the tracker's.
  void sync();
  /// At the end of the input: a loop search still pending is applied.
  void finish();

  const Trajectory& trajectory() const { return corrected_; }
  /// How many times a loop closure rewrote the past trajectory so far.
  std::size_t corrections() const { return corrections_; }
  const LoopClosingBackEnd& backEnd() const { return back_end_; }
  /// How many times the front end's map was rebuilt from the graph (once
  /// per accepted closure).
  std::size_t frontMapRebuilds() const { return front_map_rebuilds_; }

 private:
  void recomputeAll();
  TimedPose correctedSample(std::size_t i) const;
  void updateFrontMap(bool closed);

  IcpPoseTracker& tracker_;
  LoopClosingBackEnd back_end_;
  std::vector<ScanAnchor> sample_anchor_;  ///< per sample of the tracker's trajectory
  Trajectory corrected_;
  TimedPose corrected_front_last_;  ///< the tracker's last sample when last synced
  std::size_t corrections_ = 0;
  std::optional<Pose2>
      last_update_;  ///< the front end's pose when its map was last trimmed or rebuilt
  std::size_t front_map_rebuilds_ = 0;
};

}  // namespace pmap::poses
