// Issue 15 item 6: the pose laser's occupancy grid and simple map, from the
// final trajectory, written in MRPT's formats and read back by MRPT.
#include "pmap/poses/laser_maps.h"

#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>

#include "rawlog_fixtures.h"

namespace pmap::poses {
namespace {

constexpr double kHalf = 5.0;  // the room: walls at x, y = +-5 m

// A 360-beam scan taken at (x, y, yaw) in the square room; beams whose index
// is in [max_from, max_to) read max range (no return).
mrpt::obs::CObservation2DRangeScan::Ptr roomScan(double x, double y, double yaw, int max_from = 0,
                                                 int max_to = 0) {
  auto s = std::make_shared<mrpt::obs::CObservation2DRangeScan>();
  const int n = 361;
  s->aperture = static_cast<float>(2.0 * M_PI);
  s->maxRange = 80.0f;
  s->resizeScan(n);
  for (int i = 0; i < n; ++i) {
    const double a = yaw - M_PI + 2.0 * M_PI * i / (n - 1);
    const double c = std::cos(a), sn = std::sin(a);
    double r = 1e9;
    if (std::abs(c) > 1e-9)
      r = std::min(r, ((c > 0 ? kHalf : -kHalf) - x) / c);
    if (std::abs(sn) > 1e-9)
      r = std::min(r, ((sn > 0 ? kHalf : -kHalf) - y) / sn);
    const bool max_range = i >= max_from && i < max_to;
    s->setScanRange(i, max_range ? s->maxRange : static_cast<float>(r));
    s->setScanRangeValidity(i, true);  // as CARMEN logs flag max-range readings
  }
  return s;
}

float occupancy(const mrpt::maps::COccupancyGridMap2D& g, double x, double y) {
  return g.getPos(static_cast<float>(x), static_cast<float>(y));
}

// The lowest free probability (the most occupied) of the cells within one
// cell of (x, y): a wall on a cell boundary may land on either side.
float wallOccupancy(const mrpt::maps::COccupancyGridMap2D& g, double x, double y) {
  const double r = g.getResolution();
  float lowest = 1.0f;
  for (const double dx : {-r, 0.0, r}) {
    for (const double dy : {-r, 0.0, r}) {
      lowest = std::min(lowest, occupancy(g, x + dx, y + dy));
    }
  }
  return lowest;
}

TEST(LaserMaps, Item15_TheGridShowsTheRoomAtTheFinalPoses) {
  LaserMapOptions o;
  LaserScanLog log(o);
  Trajectory traj;
  // Five scans along y = 0, each 0.5 m apart; the front end's poses (given
  // to add) are offset by 3 m: only the final trajectory places the scans.
  for (int k = 0; k < 5; ++k) {
    const double t = k;
    const double x = -1.0 + 0.5 * k;
    log.add(t, mrpt::math::TPose3D(x + 3.0, 0, 0, 0, 0, 0), roomScan(x, 0.0, 0.0));
    traj.append(t, mrpt::math::TPose3D(x, 0, 0, 0, 0, 0));
  }
  ASSERT_EQ(log.size(), 5u);
  const auto maps = buildLaserMaps(log, traj, 1.0);
  ASSERT_TRUE(maps);
  EXPECT_EQ(maps->info.scans, 5u);
  EXPECT_NEAR(maps->info.resolution_m, 0.05, 1e-6);
  for (const double along : {-4.0, -2.0, 0.0, 2.0, 4.0}) {
    EXPECT_LT(wallOccupancy(maps->grid, kHalf, along), 0.3) << along;  // walls occupied
    EXPECT_LT(wallOccupancy(maps->grid, along, -kHalf), 0.3) << along;
    EXPECT_GT(occupancy(maps->grid, along, 0.5 * along), 0.7) << along;  // the inside free
  }
  EXPECT_NEAR(occupancy(maps->grid, kHalf + 2.0, 0.0), 0.5, 1e-3);  // behind the wall: unknown
  EXPECT_EQ(maps->simplemap.size(), 5u);
}

TEST(LaserMaps, Item15_MaxRangeReadingsAreNotObstacles) {
  LaserScanLog log{LaserMapOptions{}};
  Trajectory traj;
  log.add(0.0, {}, roomScan(0, 0, 0, 170, 191));  // the beams towards +x read max range
  traj.append(0.0, {});
  const auto maps = buildLaserMaps(log, traj, 1.0);
  ASSERT_TRUE(maps);
  EXPECT_GE(wallOccupancy(maps->grid, kHalf, 0.0), 0.5);             // not seen as a wall there
  EXPECT_LT(wallOccupancy(maps->grid, -kHalf, 0.0), 0.3);            // the opposite wall is
  EXPECT_LE(maps->info.x_max, LaserMapOptions{}.max_range_m + 0.1);  // nothing at 80 m
}

TEST(LaserMaps, Item15_ScansAreKeptByMotionAndTheGridStaysWithinItsBudget) {
  LaserMapOptions o;
  o.max_cells = 100'000;  // the 40 x 40 m extent (20 m range around) at 5 cm is 640k cells
  LaserScanLog log(o);
  Trajectory traj;
  for (int k = 0; k < 100; ++k) {  // standing still: one scan kept
    log.add(0.01 * k, {}, roomScan(0, 0, 0));
  }
  log.add(2.0, mrpt::math::TPose3D(0.1, 0, 0, 0, 0, 0), roomScan(0, 0, 0));  // 0.1 m: not kept
  log.add(3.0, mrpt::math::TPose3D(0, 0, 0, 0.2, 0, 0), roomScan(0, 0, 0));  // 11.5 deg: kept
  EXPECT_EQ(log.size(), 2u);
  traj.append(0.0, {});
  traj.append(3.0, {});
  const auto maps = buildLaserMaps(log, traj, 5.0);
  ASSERT_TRUE(maps);
  EXPECT_LE(static_cast<double>(maps->info.cols) * maps->info.rows, 1.1 * o.max_cells);
  EXPECT_GT(maps->info.resolution_m, 0.05);
}

TEST(LaserMaps, Item15_ScansWithoutAPoseAreCountedAndNoPoseMeansNoMaps) {
  LaserScanLog log{LaserMapOptions{}};
  log.add(10.0, {}, roomScan(0, 0, 0));
  Trajectory traj;
  EXPECT_FALSE(buildLaserMaps(log, traj, 1.0));
  traj.append(0.0, {});
  traj.append(1.0, {});
  EXPECT_FALSE(buildLaserMaps(log, traj, 1.0));  // t = 10 is outside the trajectory
  log.add(11.0, mrpt::math::TPose3D(1, 0, 0, 0, 0, 0), roomScan(0, 0, 0));
  traj.append(11.0, {});
  const auto maps = buildLaserMaps(log, traj, 20.0);
  ASSERT_TRUE(maps);
  EXPECT_EQ(maps->info.scans, 2u);  // the gap 1 -> 11 s is allowed here
  const auto strict = buildLaserMaps(log, traj, 1.0);
  ASSERT_TRUE(strict);
  EXPECT_EQ(strict->info.scans, 1u);
  EXPECT_EQ(strict->info.scans_unplaced, 1u);
}

TEST(LaserMaps, Item15_TheFilesAreReadBackByMrpt) {
  LaserScanLog log{LaserMapOptions{}};
  Trajectory traj;
  log.add(0.0, {}, roomScan(0, 0, 0));
  traj.append(0.0, {});
  const auto maps = buildLaserMaps(log, traj, 1.0);
  ASSERT_TRUE(maps);
  const auto dir = testing::freshTestDir("laser_maps");
  writeGridMap((dir / "grid.gridmap.gz").string(), maps->grid);
  writeSimpleMap((dir / "map.simplemap").string(), maps->simplemap);
  writeGridPng((dir / "grid.png").string(), maps->grid);
  EXPECT_GT(std::filesystem::file_size(dir / "grid.png"), 100u);

  mrpt::maps::COccupancyGridMap2D grid;
  mrpt::io::CFileGZInputStream g((dir / "grid.gridmap.gz").string());
  mrpt::serialization::archiveFrom(g) >> grid;
  EXPECT_EQ(grid.getSizeX(), maps->grid.getSizeX());
  EXPECT_EQ(grid.getSizeY(), maps->grid.getSizeY());
  EXPECT_FLOAT_EQ(wallOccupancy(grid, kHalf, 1.0), wallOccupancy(maps->grid, kHalf, 1.0));
  EXPECT_LT(wallOccupancy(grid, kHalf, 1.0), 0.3);

  mrpt::maps::CSimpleMap simple;
  mrpt::io::CFileGZInputStream s((dir / "map.simplemap").string());
  mrpt::serialization::archiveFrom(s) >> simple;
  ASSERT_EQ(simple.size(), 1u);
  mrpt::poses::CPose3DPDF::Ptr pose;
  mrpt::obs::CSensoryFrame::Ptr frame;
  simple.get(0, pose, frame);
  EXPECT_TRUE(frame->getObservationByClass<mrpt::obs::CObservation2DRangeScan>());
}

TEST(LaserMapOptions, Item15_Validate) {
  std::string why;
  EXPECT_TRUE(LaserMapOptions{}.validate(&why));
  LaserMapOptions o;
  o.resolution_m = 0.0;
  EXPECT_FALSE(o.validate(&why));
  o = {};
  o.max_range_m = -1.0;
  EXPECT_FALSE(o.validate(&why));
  o = {};
  o.max_range_m = std::nan("");
  EXPECT_FALSE(o.validate(&why));
}

}  // namespace
}  // namespace pmap::poses
