// The pose stage: MRPT's CMetricMapBuilderICP fed with odometry and the pose
// laser only (it scan-matches every observation it is handed, so structure
// scans and images never reach it). Configured from the ini's [ICP] and
// [MappingApplication] sections through MRPT's own loaders (read through
// config::StrictMrptConfig by the caller).
//
// A trajectory sample is recorded after every odometry reading (the pose
// propagated by odometry) and after every pose-laser scan (the ICP-corrected
// pose at the scan's timestamp; a later sample at the same time replaces the
// earlier one).
#pragma once

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservation.h>
#include <Eigen/Core>

#include <memory>
#include <vector>

#include "pmap/poses/trajectory.h"

namespace pmap::poses {

struct PoseStats {
  std::size_t odometry_readings = 0;
  std::size_t scans_matched = 0;  ///< pose-laser scans handed to ICP
  std::size_t non_monotonic = 0;  ///< samples refused: timestamp older than the last
  /// sf-format actions without a timestamp that took their frame's time
  /// (filled by PoseStage), and those dropped for lack of any time.
  std::size_t actions_timed_by_frame = 0;
  std::size_t actions_without_time = 0;
};

class IcpPoseTracker {
 public:
  /// Loads ICP_options from [MappingApplication] (incl. its map initializers
  /// and alwaysInsertByClass) and ICP_params from [ICP], then initializes
  /// the builder. MRPT's loaders throw std::exception for bad values
  /// (config::StrictMrptConfig::throwLoaderError names the key).
  explicit IcpPoseTracker(const mrpt::config::CConfigFileBase& config);
  ~IcpPoseTracker();

  /// Observations-only format: an odometry reading or a pose-laser scan.
  void processObservation(const mrpt::obs::CObservation::Ptr& obs, bool is_odometry);

  /// Actions + sensory-frames format: one frame's odometry action (may be
  /// null) and its pose-laser scans / odometry observations.
  void processFrame(const mrpt::obs::CActionCollection::Ptr& action,
                    const std::vector<mrpt::obs::CObservation::Ptr>& observations);

  const Trajectory& trajectory() const { return trajectory_; }

  /// The front end's current pose (its own frame).
  mrpt::math::TPose3D currentPose() const;

  const PoseStats& stats() const { return stats_; }

  /// Replaces the builder's point map with `points` (x, y in the front
  /// end's own frame, m): the local map the loop-closing stage rebuilds from
  /// the pose graph (loop_closing_stage.h). The pose estimate is kept.
  void replaceMap(const std::vector<Eigen::Vector2d>& points);
  /// Drops the builder's map points farther than radius_m from (x, y) (the
  /// front end's frame, m): MRPT's kd-tree, rebuilt at every insertion, then
  /// stays the size of the neighbourhood instead of the whole run's.
  void clipMap(double x, double y, double radius_m);

 private:
  void recordPose(double t);

  class Impl;
  std::unique_ptr<Impl> impl_;
  Trajectory trajectory_;
  PoseStats stats_;
};

}  // namespace pmap::poses
