#include "rawlog_fixtures.h"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <fstream>
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

// Horizontal scan from (x, 0) looking +x: the side walls and an end wall.
CObservation2DRangeScan::Ptr horizontalScan(double t, double x) {
  auto s = std::make_shared<CObservation2DRangeScan>();
  s->sensorLabel = "LASER_H";
  s->timestamp = mrpt::Clock::fromDouble(t);
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

// Vertical scan across the corridor (pitch -90 deg): beam 0 right, 90 up.
CObservation2DRangeScan::Ptr verticalScan(double t) {
  auto s = std::make_shared<CObservation2DRangeScan>();
  s->sensorLabel = "LASER_V";
  s->timestamp = mrpt::Clock::fromDouble(t);
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
  }
  return s;
}

template <class Stream>
void writeAll(Stream& out, const FixtureOptions& o) {
  auto arch = mrpt::serialization::archiveFrom(out);
  mrpt::poses::CPose2D previous(0, 0, 0);
  if (o.format == FixtureFormat::kSensoryFrames && o.leading_frame) {
    CSensoryFrame sf;
    sf.insert(horizontalScan(kT0 - 0.2, 0.0));
    arch << sf;
  }
  for (int k = 0; k < o.cycles; ++k) {
    const double t = kT0 + 0.2 * k;
    const mrpt::poses::CPose2D odo(o.speed_mps * 0.2 * k, 0, 0);
    if (o.format == FixtureFormat::kObservations) {
      auto odom = std::make_shared<CObservationOdometry>();
      odom->sensorLabel = "ODOMETRY";
      odom->timestamp = mrpt::Clock::fromDouble(t);
      odom->odometry = odo;
      arch << *odom << *horizontalScan(t, odo.x());
      if (o.vertical) {
        arch << *verticalScan(t + 0.1);
      }
    } else {
      CActionCollection acts;
      CActionRobotMovement2D move;
      move.timestamp = mrpt::Clock::fromDouble(t);
      move.computeFromOdometry(odo - previous, CActionRobotMovement2D::TMotionModelOptions());
      acts.insert(move);
      CSensoryFrame sf;
      sf.insert(horizontalScan(t, odo.x()));
      if (o.vertical) {
        sf.insert(verticalScan(t + 0.1));
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
