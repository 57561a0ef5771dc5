// Places structure scans in the world with the pose interpolated at their own
// timestamp. Scans wait until the trajectory around their time is final:
// with ICP poses the newest trajectory sample may still be replaced (an
// odometry-propagated pose corrected by the scan matcher at the same time),
// so a scan is placed once a sample exists after the one that follows it.
// This makes the result independent of how observations are grouped in the
// rawlog (observations-only vs sensory frames).
#pragma once

#include <deque>
#include <functional>
#include <vector>

#include "pmap/input/structure_points.h"
#include "pmap/points/point_map.h"
#include "pmap/poses/trajectory.h"

namespace pmap::points {

struct PlacementStats {
  std::size_t placed = 0;
  std::size_t without_pose = 0;  ///< outside the trajectory or in a gap > max_pose_gap_s
};

class ScanPlacer {
 public:
  using OnPlaced = std::function<void(const input::StructureScan&, std::size_t scan_record)>;

  ScanPlacer(PointMap& map, double max_pose_gap_s, OnPlaced on_placed)
      : map_(map), max_gap_s_(max_pose_gap_s), on_placed_(std::move(on_placed)) {}

  void add(input::StructureScan scan) { pending_.push_back(std::move(scan)); }

  /// Places the pending scans whose pose is final. `final_all`: the whole
  /// trajectory is final (given poses, or the end of the input).
  void drain(const poses::Trajectory& trajectory, bool final_all);

  /// Re-places every placed scan at `trajectory`'s pose at its time, after
  /// the past trajectory changed (a loop closure): scans whose pose moved by
  /// more than 0.1 mm or 1e-5 rad move rigidly (PointMap::moveScan); scans
  /// the trajectory no longer covers stay. Returns the moved scan records.
  /// Work: O(placed scans + moved points).
  std::vector<std::size_t> follow(const poses::Trajectory& trajectory);

  /// Places every pending scan at `pose` (the single-frame identity case).
  void placeAllAt(const mrpt::math::TPose3D& pose);

  std::size_t pending() const { return pending_.size(); }
  const PlacementStats& stats() const { return stats_; }

 private:
  void place(const input::StructureScan& scan, const mrpt::math::TPose3D& pose);

  PointMap& map_;
  double max_gap_s_;
  OnPlaced on_placed_;
  std::deque<input::StructureScan> pending_;
  PlacementStats stats_;
};

}  // namespace pmap::points
