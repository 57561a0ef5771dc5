// Feeds the pose-relevant observations of each input step to the ICP
// tracker: odometry (readings or sf-format actions) and pose-laser scans,
// nothing else. With given poses (--poses) the trajectory is fixed and steps
// are ignored.
#pragma once

#include <memory>
#include <string>

#include "pmap/input/observation_source.h"
#include "pmap/poses/icp_pose_tracker.h"
#include "pmap/poses/trajectory.h"

namespace pmap::poses {

class PoseStage {
 public:
  /// ICP poses.
  explicit PoseStage(std::unique_ptr<IcpPoseTracker> tracker);
  /// Given poses.
  explicit PoseStage(Trajectory given);

  /// Throws InputError (naming the record) when MRPT rejects an observation.
  void process(const input::InputStep& step, const std::string& file);

  const Trajectory& trajectory() const;
  /// True when every sample of trajectory() is final up to its last one
  /// (given poses); otherwise the last sample may still be replaced.
  bool fixed() const { return !tracker_; }
  const char* source() const { return tracker_ ? "icp" : "file"; }
  PoseStats stats() const { return tracker_ ? tracker_->stats() : PoseStats{}; }

 private:
  std::unique_ptr<IcpPoseTracker> tracker_;
  Trajectory given_;
};

}  // namespace pmap::poses
