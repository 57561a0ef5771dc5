#include "rawlog_fixtures.h"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/datetime.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <memory>
#include <vector>

namespace pmap::testing {
namespace fs = std::filesystem;
using namespace mrpt::obs;

namespace {

constexpr double kT0 = 1767225600.0;
constexpr double kHalfWidth = 2.0;
constexpr double kHeight = 2.5;
constexpr double kEndWallX = 6.0;

// Seconds since 1970 as an MRPT timestamp; 0 is INVALID_TIMESTAMP.
mrpt::Clock::time_point stamp(double t) {
  return t == 0.0 ? INVALID_TIMESTAMP : mrpt::Clock::fromDouble(t);
}

// Horizontal scan from (x, 0) looking +x: the side walls and an end wall.
CObservation2DRangeScan::Ptr horizontalScan(double t, double x) {
  auto s = std::make_shared<CObservation2DRangeScan>();
  s->sensorLabel = "LASER_H";
  s->timestamp = stamp(t);
  s->aperture = M_PI;
  s->rightToLeft = true;
  s->maxRange = 30;
  s->sensorPose = mrpt::poses::CPose3D(0, 0, 0.4, 0, 0, 0);
  s->resizeScan(181);
  for (int i = 0; i < 181; ++i) {
    const double a = -M_PI / 2 + i * M_PI / 180;
    const double sy = std::sin(a);
    const double cx = std::cos(a);
    const double r_side = std::abs(sy) > 1e-6 ? kHalfWidth / std::abs(sy) : 1e9;
    const double r_end = cx > 1e-6 ? (kEndWallX - x - 0.0) / cx : 1e9;
    const double r = std::min(r_side, r_end);
    s->setScanRange(i, static_cast<float>(std::min(r, 30.0)));
    s->setScanRangeValidity(i, r <= 30.0);
  }
  return s;
}

// Replaces beam i's range as `ranges` asks.
void damageRange(CObservation2DRangeScan& s, int i, int cycle, StructureRanges ranges) {
  switch (ranges) {
    case StructureRanges::kCorridor:
      break;
    case StructureRanges::kAllInvalid:
      s.setScanRangeValidity(i, false);
      break;
    case StructureRanges::kNanValid:
      if (i % 7 == 0) {
        s.setScanRange(i, i % 14 == 0 ? std::numeric_limits<float>::quiet_NaN()
                                      : std::numeric_limits<float>::infinity());
      }
      break;
    case StructureRanges::kNegative:
      if (i % 5 == 0) {
        s.setScanRange(i, i % 10 == 0 ? 0.0f : -1.5f);
      }
      break;
    case StructureRanges::kScattered: {
      // A fixed pseudo-random range in [0.5, 10.5) m per beam and cycle.
      const unsigned h = (static_cast<unsigned>(i) * 2654435761u) ^
                         (static_cast<unsigned>(cycle) * 40503u + 0x9e37u);
      s.setScanRange(i, 0.5f + static_cast<float>((h >> 8) % 10000) / 1000.0f);
      break;
    }
  }
}

// Vertical scan across the corridor (pitch -90 deg): beam 0 right, 90 up.
CObservation2DRangeScan::Ptr verticalScan(double t, const FixtureOptions& o, int cycle) {
  auto s = std::make_shared<CObservation2DRangeScan>();
  s->sensorLabel = o.laser_v_label;
  s->timestamp = stamp(t);
  s->aperture = M_PI;
  s->rightToLeft = true;
  s->maxRange = 30;
  s->sensorPose = mrpt::poses::CPose3D(0, 0, 0.3, 0, -M_PI / 2, 0);
  s->resizeScan(181);
  const double up = kHeight - 0.3;
  for (int i = 0; i < 181; ++i) {
    const double a = -M_PI / 2 + i * M_PI / 180;  // angle from "up" towards left
    const double c = std::cos(a);
    const double sn = std::abs(std::sin(a));
    const double r_ceiling = c > 1e-9 ? up / c : 1e9;
    const double r_wall = sn > 1e-9 ? kHalfWidth / sn : 1e9;
    s->setScanRange(i, static_cast<float>(std::min(r_ceiling, r_wall)));
    s->setScanRangeValidity(i, true);
    damageRange(*s, i, cycle, o.ranges);
  }
  return s;
}

// Timestamp of cycle k (seconds), damaged as `fault` asks.
double cycleTime(int k, TimestampFault fault) {
  const bool hit = k > 0 && k % 4 == 0;
  switch (fault) {
    case TimestampFault::kNone:
      break;
    case TimestampFault::kZero:
      return hit ? 0.0 : kT0 + 0.2 * k;
    case TimestampFault::kDuplicate:
      return kT0 + 0.2 * (hit ? k - 1 : k);
    case TimestampFault::kBackwards:
      return kT0 + 0.2 * k - (hit ? 1.2 : 0.0);
  }
  return kT0 + 0.2 * k;
}

// The odometry of cycle k.
mrpt::poses::CPose2D cycleOdometry(int k, const FixtureOptions& o) {
  if (o.nan_odometry && k == 5) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return mrpt::poses::CPose2D(nan, nan, nan);
  }
  return mrpt::poses::CPose2D(o.offset_x_m + o.speed_mps * 0.2 * k, 0, 0);
}

template <class Stream>
void writeAll(Stream& out, const FixtureOptions& o) {
  auto arch = mrpt::serialization::archiveFrom(out);
  mrpt::poses::CPose2D previous(o.offset_x_m, 0, 0);
  if (o.format == FixtureFormat::kSensoryFrames && o.leading_frame) {
    CSensoryFrame sf;
    sf.insert(horizontalScan(kT0 - 0.2, 0.0));
    arch << sf;
  }
  for (int k = 0; k < o.cycles; ++k) {
    const double t = cycleTime(k, o.timestamps);
    const mrpt::poses::CPose2D odo = cycleOdometry(k, o);
    const double x = o.speed_mps * 0.2 * k;  // along the corridor, for the ranges
    const double t_v = t == 0.0 ? 0.0 : t + 0.1;
    if (o.format == FixtureFormat::kObservations) {
      auto odom = std::make_shared<CObservationOdometry>();
      odom->sensorLabel = "ODOMETRY";
      odom->timestamp = stamp(t);
      odom->odometry = odo;
      arch << *odom << *horizontalScan(t, x);
      if (o.vertical) {
        arch << *verticalScan(t_v, o, k);
      }
    } else {
      CActionCollection acts;
      CActionRobotMovement2D move;
      move.timestamp = stamp(t);
      move.computeFromOdometry(odo - previous, CActionRobotMovement2D::TMotionModelOptions());
      acts.insert(move);
      CSensoryFrame sf;
      sf.insert(horizontalScan(t, x));
      if (o.vertical) {
        sf.insert(verticalScan(t_v, o, k));
      }
      arch << acts << sf;
    }
    previous = odo;
  }
}

}  // namespace

void writeFixtureRawlog(const fs::path& path, const FixtureOptions& options) {
  if (options.gzip) {
    mrpt::io::CFileGZOutputStream out(path.string());
    writeAll(out, options);
  } else {
    mrpt::io::CFileOutputStream out(path.string());
    writeAll(out, options);
  }
}

fs::path freshTestDir(const std::string& name) {
  const fs::path dir = fs::path(PMAP_TEST_TMP_DIR) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void truncateCopy(const fs::path& src, const fs::path& dst, double fraction) {
  std::ifstream in(src, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto n = static_cast<size_t>(fraction * static_cast<double>(bytes.size()));
  std::ofstream out(dst, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(n));
}

}  // namespace pmap::testing
