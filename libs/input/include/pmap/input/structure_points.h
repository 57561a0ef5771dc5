// Structure observations turned into finite 3D points in the ROBOT frame.
// This is the validation boundary (CONVENTIONS.md): every point handed on is
// finite; everything dropped is counted by reason.
#pragma once

#include <mrpt/math/TPose3D.h>
#include <mrpt/obs/CObservation.h>

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace pmap::input {

/// Why measurements were dropped.
struct DropCounts {
  std::uint64_t invalid = 0;       ///< flagged invalid by the sensor (no return)
  std::uint64_t non_finite = 0;    ///< NaN/Inf range or coordinate with validity 1
  std::uint64_t out_of_range = 0;  ///< range <= 0 or above the sensor's max range
  std::uint64_t total() const { return invalid + non_finite + out_of_range; }
  DropCounts& operator+=(const DropCounts& o);
};

/// The points of one structure observation.
struct StructureScan {
  std::int64_t index = -1;  ///< structure scan index in the file
  double timestamp = 0;     ///< seconds (mrpt::Clock::toDouble)
  std::string label;
  mrpt::math::TPose3D sensor_pose;  ///< sensor on the robot
  /// Measurement grid: beam = row * cols + col. A 2D scan is 1 x N; a range
  /// image H x W; unorganised clouds are 1 x N with `organised` false.
  int rows = 1;
  int cols = 0;
  bool organised = true;
  std::vector<Eigen::Vector3d> points;  ///< robot frame, finite
  std::vector<std::int32_t> beams;      ///< grid index of each point
  DropCounts dropped;
  std::uint64_t measurements() const { return static_cast<std::uint64_t>(rows) * cols; }
};

/// Extracts the points of a structure observation (CObservation2DRangeScan,
/// CObservation3DRangeScan, CObservationVelodyneScan, CObservationPointCloud).
/// A NaN in the sensor pose drops the whole observation (counted as
/// non_finite). Throws InputError for other classes.
StructureScan extractStructureScan(const mrpt::obs::CObservation& obs, std::int64_t index);

}  // namespace pmap::input
