// The pose laser's maps, for MRPT users (issue 15 item 6; doc/outputs.md):
// an occupancy grid (grid.png, grid.gridmap.gz: MRPT's COccupancyGridMap2D,
// serialized and gzipped, as RawLogViewer and the icp-slam app write it)
// and a simple map (map.simplemap: each kept scan with its pose, which
// RawLogViewer opens and MRPT's map builders read). Both use the final
// trajectory, so with loop closure they show the optimised poses.
//
// Scans are kept as they arrive, one per keep_distance_m of travel or
// keep_angle_deg of turn (the memory grows with the path, not the log's
// rate), and placed at the end. Max-range readings (flagged valid in CARMEN
// logs) are not obstacles; beams are inserted up to max_range_m. The grid
// never exceeds max_cells: its resolution doubles until the path's extent
// (plus max_range_m around it) fits, and summary.json says which it used.
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/math/TPose3D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "pmap/poses/trajectory.h"

namespace pmap::poses {

struct LaserMapOptions {
  bool enabled = true;  ///< [Output] laser_maps: write grid.png, grid.gridmap.gz, map.simplemap
  double resolution_m = 0.05;          ///< [Output] grid_resolution_m: the grid's cell (m)
  double max_range_m = 20.0;           ///< [Output] grid_max_range_m: beams inserted up to this (m)
  double keep_distance_m = 0.2;        ///< a scan kept per this much travel (m)
  double keep_angle_deg = 10.0;        ///< ... or turn (deg)
  std::size_t max_cells = 25'000'000;  ///< the grid's cell budget (about 50 MB)
  bool validate(std::string* why) const;
};

/// The pose-laser scans kept for the maps, with their times.
class LaserScanLog {
 public:
  explicit LaserScanLog(LaserMapOptions options) : options_(options) {}
  /// A pose-laser scan at `t`, taken at about `pose` (any frame: only the
  /// motion since the last kept scan matters).
  void add(double t, const mrpt::math::TPose3D& pose,
           const mrpt::obs::CObservation2DRangeScan::Ptr& scan);
  std::size_t size() const { return scans_.size(); }
  const LaserMapOptions& options() const { return options_; }

  struct Kept {
    double t = 0;
    mrpt::obs::CObservation2DRangeScan::Ptr scan;
  };
  const std::vector<Kept>& scans() const { return scans_; }

 private:
  LaserMapOptions options_;
  std::vector<Kept> scans_;
  std::optional<mrpt::math::TPose3D> last_;
};

struct GridInfo {
  double resolution_m = 0;  ///< the cell used (coarser than asked when the extent needed it)
  double x_min = 0, x_max = 0, y_min = 0, y_max = 0;  ///< the grid's extent (m)
  std::size_t cols = 0, rows = 0;
  std::size_t scans = 0;           ///< inserted
  std::size_t scans_unplaced = 0;  ///< kept, but no pose at their time
};

struct LaserMaps {
  mrpt::maps::COccupancyGridMap2D grid;
  mrpt::maps::CSimpleMap simplemap;
  GridInfo info;
};

/// The kept scans placed along `trajectory` (poses interpolated within
/// max_gap_s). Empty (nullopt) when no scan could be placed.
std::optional<LaserMaps> buildLaserMaps(const LaserScanLog& log, const Trajectory& trajectory,
                                        double max_gap_s);

/// grid.png (free white, occupied black, unknown grey; +y up),
/// grid.gridmap.gz and map.simplemap (MRPT serialization, gzipped).
void writeGridPng(const std::string& path, const mrpt::maps::COccupancyGridMap2D& grid);
void writeGridMap(const std::string& path, const mrpt::maps::COccupancyGridMap2D& grid);
void writeSimpleMap(const std::string& path, const mrpt::maps::CSimpleMap& map);

}  // namespace pmap::poses
