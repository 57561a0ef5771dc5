// The measurements in the world frame: every finite structure point with the
// scan and beam it came from, plus where each scan's sensor was. This is the
// input of the EM stage and of every output file (points.ply, scans.csv).
#pragma once

#include <mrpt/math/TPose3D.h>

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "pmap/input/structure_points.h"

namespace pmap::points {

/// One placed structure scan.
struct ScanRecord {
  std::int64_t index = -1;  ///< structure scan index in the file
  double timestamp = 0;
  std::string label;
  mrpt::math::TPose3D robot_pose;   ///< world
  mrpt::math::TPose3D sensor_pose;  ///< world (robot pose + sensor pose on the robot)
  std::size_t first_point = 0;      ///< range in PointMap
  std::size_t num_points = 0;
  int rows = 1;  ///< measurement grid (see input::StructureScan)
  int cols = 0;
  bool organised = true;
};

class PointMap {
 public:
  /// Transforms `scan` (robot frame) by `robot_pose` and appends its points.
  /// Returns the index of the new ScanRecord.
  std::size_t addScan(const input::StructureScan& scan, const mrpt::math::TPose3D& robot_pose);

  /// Moves scan `record` rigidly to a new robot pose: its points, robot and
  /// sensor poses follow (p' = T_new T_old^-1 p). Point indices are kept.
  void moveScan(std::size_t record, const mrpt::math::TPose3D& robot_pose);

  std::size_t size() const { return xyz_.size(); }
  const std::vector<Eigen::Vector3d>& xyz() const { return xyz_; }
  const std::vector<std::int32_t>& scanIndex() const { return scan_; }
  const std::vector<std::int32_t>& beamIndex() const { return beam_; }
  const std::vector<ScanRecord>& scans() const { return scans_; }

 private:
  std::vector<Eigen::Vector3d> xyz_;
  std::vector<std::int32_t> scan_;
  std::vector<std::int32_t> beam_;
  std::vector<ScanRecord> scans_;
};

}  // namespace pmap::points
