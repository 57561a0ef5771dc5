#include "pmap/poses/laser_maps.h"

#include <mrpt/core/bits_math.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "pmap/common/error.h"
#include "pmap/poses/loop_closing_stage.h"

namespace pmap::poses {
namespace {

// The scan as the grid should see it: only its returns are valid
// (isReturn: max-range readings are no obstacle).
mrpt::obs::CObservation2DRangeScan withoutMaxRange(const mrpt::obs::CObservation2DRangeScan& s) {
  mrpt::obs::CObservation2DRangeScan out = s;
  for (std::size_t i = 0; i < out.getScanSize(); ++i) {
    if (!isReturn(out, i)) {
      out.setScanRangeValidity(i, false);
    }
  }
  return out;
}

struct Placed {
  mrpt::poses::CPose3D pose;
  const LaserScanLog::Kept* kept = nullptr;
};

// The grid's extent and cell: the placed poses plus max_range_m around them,
// at the asked resolution or coarser, within the cell budget.
GridInfo gridFor(const std::vector<Placed>& placed, const LaserMapOptions& o) {
  GridInfo g;
  g.x_min = g.y_min = std::numeric_limits<double>::infinity();
  g.x_max = g.y_max = -std::numeric_limits<double>::infinity();
  for (const Placed& p : placed) {
    g.x_min = std::min(g.x_min, p.pose.x() - o.max_range_m);
    g.x_max = std::max(g.x_max, p.pose.x() + o.max_range_m);
    g.y_min = std::min(g.y_min, p.pose.y() - o.max_range_m);
    g.y_max = std::max(g.y_max, p.pose.y() + o.max_range_m);
  }
  g.resolution_m = o.resolution_m;
  const auto cells = [&](double r) {
    return ((g.x_max - g.x_min) / r) * ((g.y_max - g.y_min) / r);
  };
  while (cells(g.resolution_m) > static_cast<double>(o.max_cells)) {
    g.resolution_m *= 2.0;
  }
  return g;
}

template <typename T>
void writeGz(const std::string& path, const T& object, const char* what) {
  mrpt::io::CFileGZOutputStream f;
  if (!f.open(path)) {
    throw OutputError(path + ": cannot write the " + std::string(what));
  }
  auto archive = mrpt::serialization::archiveFrom(f);
  archive << object;
}

}  // namespace

bool LaserMapOptions::validate(std::string* why) const {
  if (!(resolution_m >= 0.005 && resolution_m <= 10.0)) {
    *why = "grid_resolution_m must be in [0.005, 10] m";
    return false;
  }
  if (!(max_range_m > 0.0 && max_range_m <= 1000.0)) {
    *why = "grid_max_range_m must be in (0, 1000] m";
    return false;
  }
  if (!(keep_distance_m > 0.0) || !(keep_angle_deg > 0.0) || max_cells < 100) {
    *why = "laser map keep distance and angle must be > 0, the cell budget >= 100";
    return false;
  }
  return true;
}

void LaserScanLog::add(double t, const mrpt::math::TPose3D& pose,
                       const mrpt::obs::CObservation2DRangeScan::Ptr& scan) {
  if (!options_.enabled || !scan) {
    return;
  }
  if (last_) {
    const double moved = std::hypot(pose.x - last_->x, pose.y - last_->y);
    const double turned = std::abs(std::remainder(pose.yaw - last_->yaw, 2.0 * M_PI));
    if (moved < options_.keep_distance_m && turned < mrpt::DEG2RAD(options_.keep_angle_deg)) {
      return;
    }
  }
  last_ = pose;
  scans_.push_back({t, scan});
}

std::optional<LaserMaps> buildLaserMaps(const LaserScanLog& log, const Trajectory& trajectory,
                                        double max_gap_s) {
  std::vector<Placed> placed;
  std::size_t unplaced = 0;
  for (const LaserScanLog::Kept& k : log.scans()) {
    const auto pose = trajectory.empty() ? std::nullopt : trajectory.at(k.t, max_gap_s);
    if (!pose) {
      ++unplaced;
      continue;
    }
    placed.push_back({mrpt::poses::CPose3D(*pose), &k});
  }
  if (placed.empty()) {
    return std::nullopt;
  }
  LaserMaps maps;
  maps.info = gridFor(placed, log.options());
  GridInfo& g = maps.info;
  maps.grid.setSize(g.x_min, g.x_max, g.y_min, g.y_max, g.resolution_m);
  maps.grid.insertionOptions.maxDistanceInsertion = static_cast<float>(log.options().max_range_m);
  for (const Placed& p : placed) {
    const mrpt::obs::CObservation2DRangeScan scan = withoutMaxRange(*p.kept->scan);
    maps.grid.insertObservation(scan, p.pose);
    auto frame = std::make_shared<mrpt::obs::CSensoryFrame>();
    frame->insert(p.kept->scan);
    maps.simplemap.insert(std::make_shared<mrpt::poses::CPose3DPDFGaussian>(p.pose), frame);
  }
  g.x_min = maps.grid.getXMin();
  g.x_max = maps.grid.getXMax();
  g.y_min = maps.grid.getYMin();
  g.y_max = maps.grid.getYMax();
  g.resolution_m = maps.grid.getResolution();
  g.cols = maps.grid.getSizeX();
  g.rows = maps.grid.getSizeY();
  g.scans = placed.size();
  g.scans_unplaced = unplaced;
  return maps;
}

void writeGridPng(const std::string& path, const mrpt::maps::COccupancyGridMap2D& grid) {
  if (!grid.saveAsBitmapFile(path)) {
    throw OutputError(path + ": cannot write the occupancy grid picture");
  }
}

void writeGridMap(const std::string& path, const mrpt::maps::COccupancyGridMap2D& grid) {
  writeGz(path, grid, "occupancy grid");
}

void writeSimpleMap(const std::string& path, const mrpt::maps::CSimpleMap& map) {
  writeGz(path, map, "simple map");
}

}  // namespace pmap::poses
