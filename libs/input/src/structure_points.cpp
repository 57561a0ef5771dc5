#include "pmap/input/structure_points.h"

#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationVelodyneScan.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/system/datetime.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "pmap/common/error.h"

namespace pmap::input {
namespace {

using mrpt::poses::CPose3D;

bool finitePose(const CPose3D& p) {
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()) &&
         std::isfinite(p.yaw()) && std::isfinite(p.pitch()) && std::isfinite(p.roll());
}

bool finite(const Eigen::Vector3d& p) {
  return p.allFinite();
}

Eigen::Vector3d toRobot(const CPose3D& sensor, double x, double y, double z) {
  double gx = 0;
  double gy = 0;
  double gz = 0;
  sensor.composePoint(x, y, z, gx, gy, gz);
  return {gx, gy, gz};
}

// 2D laser: beam i at angle getScanAngle(i) in the sensor's XY plane.
void extract2D(const mrpt::obs::CObservation2DRangeScan& scan, StructureScan& out) {
  const size_t n = scan.getScanSize();
  out.cols = static_cast<int>(n);
  const CPose3D& sensor = scan.sensorPose;
  const double max_range = scan.maxRange;
  for (size_t i = 0; i < n; ++i) {
    if (!scan.getScanRangeValidity(i)) {
      ++out.dropped.invalid;
      continue;
    }
    const double r = scan.getScanRange(i);
    if (!std::isfinite(r)) {
      ++out.dropped.non_finite;
      continue;
    }
    if (r <= 0.0 || (max_range > 0 && r > max_range)) {
      ++out.dropped.out_of_range;
      continue;
    }
    const double a = scan.getScanAngle(i);
    const Eigen::Vector3d p = toRobot(sensor, r * std::cos(a), r * std::sin(a), 0.0);
    if (!finite(p)) {
      ++out.dropped.non_finite;
      continue;
    }
    out.points.push_back(p);
    out.beams.push_back(static_cast<std::int32_t>(i));
  }
}

// Range image: MRPT's unprojection (intrinsics, depth/range convention,
// sensor pose), with the pixel of every point kept as its beam index.
void extract3D(const mrpt::obs::CObservation3DRangeScan& in, StructureScan& out) {
  mrpt::obs::CObservation3DRangeScan obs = in;  // unprojectInto() writes into the observation
  obs.load();
  if (!obs.hasRangeImage) {
    out.rows = 0;
    return;
  }
  out.rows = static_cast<int>(obs.rangeImage.rows());
  out.cols = static_cast<int>(obs.rangeImage.cols());
  mrpt::maps::CSimplePointsMap cloud;
  mrpt::obs::T3DPointsProjectionParams pp;
  pp.takeIntoAccountSensorPoseOnRobot = true;
  obs.unprojectInto(cloud, pp);
  const auto& xs = cloud.getPointsBufferRef_x();
  const auto& ys = cloud.getPointsBufferRef_y();
  const auto& zs = cloud.getPointsBufferRef_z();
  const std::uint64_t valid_pixels = xs.size();
  for (size_t i = 0; i < xs.size(); ++i) {
    const Eigen::Vector3d p(xs[i], ys[i], zs[i]);
    if (!finite(p)) {
      ++out.dropped.non_finite;
      continue;
    }
    out.points.push_back(p);
    out.beams.push_back(obs.points3D_idxs_y[i] * out.cols + obs.points3D_idxs_x[i]);
  }
  out.dropped.invalid += out.measurements() - valid_pixels;
}

template <class Vec>
void extractCloud(const Vec& xs, const Vec& ys, const Vec& zs, const CPose3D& sensor,
                  StructureScan& out) {
  out.organised = false;
  out.cols = static_cast<int>(xs.size());
  for (size_t i = 0; i < xs.size(); ++i) {
    if (!std::isfinite(xs[i]) || !std::isfinite(ys[i]) || !std::isfinite(zs[i])) {
      ++out.dropped.non_finite;
      continue;
    }
    const Eigen::Vector3d p = toRobot(sensor, xs[i], ys[i], zs[i]);
    if (!finite(p)) {
      ++out.dropped.non_finite;
      continue;
    }
    out.points.push_back(p);
    out.beams.push_back(static_cast<std::int32_t>(i));
  }
}

// A rotating multi-beam lidar's sweep as a range image: row = the laser's
// rank by elevation (VLP-16 lasers fire interleaved: laser 0 at -15 deg, 1
// at +1 deg, ...), column = the azimuth in steps of the sweep's own firing
// resolution (the median azimuth step between consecutive points of one
// laser). Neighbours then lie along a ring and across to the next ring up
// or down, not only along a ring as the nearest neighbours of such a sweep
// do (its rings are 2 deg apart, its beams 0.2 deg).
void extractVelodyne(const mrpt::obs::CObservationVelodyneScan& in, const CPose3D& sensor,
                     StructureScan& out) {
  mrpt::obs::CObservationVelodyneScan v = in;
  mrpt::obs::CObservationVelodyneScan::TGeneratePointCloudParameters params;
  params.generatePerPointAzimuth = true;
  v.generatePointCloud(params);
  const auto& pc = v.point_cloud;
  const std::size_t n = pc.x.size();
  if (pc.azimuth.size() != n || pc.laser_id.size() != n || n == 0) {
    extractCloud(pc.x, pc.y, pc.z, sensor, out);  // no per-point ring data
    return;
  }
  // Each laser's elevation (median over its points) and azimuth step.
  std::map<int, std::vector<double>> elevations;
  std::map<int, double> last_azimuth;
  std::vector<double> steps;
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(pc.x[i]) || !std::isfinite(pc.y[i]) || !std::isfinite(pc.z[i]) ||
        !std::isfinite(pc.azimuth[i])) {
      continue;  // dropped below; a NaN would break the medians' ordering
    }
    const int id = pc.laser_id[i];
    elevations[id].push_back(std::atan2(pc.z[i], std::hypot(pc.x[i], pc.y[i])));
    const auto it = last_azimuth.find(id);
    if (it != last_azimuth.end()) {
      const double d = std::abs(pc.azimuth[i] - it->second);
      if (d > 1e-6 && d < 5.0) {
        steps.push_back(d);
      }
    }
    last_azimuth[id] = pc.azimuth[i];
  }
  if (steps.empty()) {
    extractCloud(pc.x, pc.y, pc.z, sensor, out);
    return;
  }
  std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2),
                   steps.end());
  const double step = steps[steps.size() / 2];
  std::vector<std::pair<double, int>> by_elevation;
  for (auto& [id, e] : elevations) {
    std::nth_element(e.begin(), e.begin() + static_cast<std::ptrdiff_t>(e.size() / 2), e.end());
    by_elevation.emplace_back(e[e.size() / 2], id);
  }
  std::sort(by_elevation.begin(), by_elevation.end());
  std::map<int, int> row_of;
  for (std::size_t r = 0; r < by_elevation.size(); ++r) {
    row_of[by_elevation[r].second] = static_cast<int>(r);
  }
  const auto wrapped = [](double az) {
    az = std::fmod(az, 360.0);
    return az < 0.0 ? az + 360.0 : az;
  };
  double lo = 360.0;
  double hi = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (std::isfinite(pc.azimuth[i])) {
      lo = std::min(lo, wrapped(pc.azimuth[i]));
      hi = std::max(hi, wrapped(pc.azimuth[i]));
    }
  }
  out.rows = static_cast<int>(by_elevation.size());
  out.cols = static_cast<int>(std::lround((std::max(hi, lo) - lo) / step)) + 1;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d p = toRobot(sensor, pc.x[i], pc.y[i], pc.z[i]);
    if (!finite(p) || !std::isfinite(pc.azimuth[i])) {
      ++out.dropped.non_finite;
      continue;
    }
    const int col = std::clamp(static_cast<int>(std::lround((wrapped(pc.azimuth[i]) - lo) / step)),
                               0, out.cols - 1);
    out.points.push_back(p);
    out.beams.push_back(row_of[pc.laser_id[i]] * out.cols + col);
  }
  // Cells of the sweep's grid without a return (no echo, too close or far).
  const std::uint64_t seen = out.points.size() + out.dropped.non_finite;
  out.dropped.invalid += out.measurements() > seen ? out.measurements() - seen : 0;
}

}  // namespace

DropCounts& DropCounts::operator+=(const DropCounts& o) {
  invalid += o.invalid;
  non_finite += o.non_finite;
  out_of_range += o.out_of_range;
  return *this;
}

StructureScan extractStructureScan(const mrpt::obs::CObservation& obs, std::int64_t index) {
  using namespace mrpt::obs;
  StructureScan out;
  out.index = index;
  out.timestamp = mrpt::Clock::toDouble(obs.timestamp);
  out.label = obs.sensorLabel;
  CPose3D sensor;
  obs.getSensorPose(sensor);
  out.sensor_pose = sensor.asTPose();
  if (!finitePose(sensor)) {
    out.cols = 1;
    out.dropped.non_finite = 1;
    return out;
  }
  if (const auto* s2 = dynamic_cast<const CObservation2DRangeScan*>(&obs)) {
    extract2D(*s2, out);
  } else if (const auto* s3 = dynamic_cast<const CObservation3DRangeScan*>(&obs)) {
    extract3D(*s3, out);
  } else if (const auto* v = dynamic_cast<const CObservationVelodyneScan*>(&obs)) {
    extractVelodyne(*v, sensor, out);
  } else if (const auto* pc = dynamic_cast<const CObservationPointCloud*>(&obs)) {
    pc->load();
    if (pc->pointcloud) {
      extractCloud(pc->pointcloud->getPointsBufferRef_x(), pc->pointcloud->getPointsBufferRef_y(),
                   pc->pointcloud->getPointsBufferRef_z(), sensor, out);
    }
  } else {
    throw InputError(std::string("not a structure observation class: ") +
                     obs.GetRuntimeClass()->className);
  }
  return out;
}

}  // namespace pmap::input
