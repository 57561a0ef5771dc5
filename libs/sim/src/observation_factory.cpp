#include "pmap/sim/observation_factory.h"

#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <cmath>

namespace pmap::sim {
namespace {

mrpt::poses::CPose3D toMrpt(const Pose6D& p) {
  return mrpt::poses::CPose3D(p.x, p.y, p.z, p.yaw, p.pitch, p.roll);
}

}  // namespace

mrpt::Clock::time_point simTimestamp(double start_time_s, double offset_s) {
  const auto ticks = static_cast<mrpt::Clock::rep>(std::llround(offset_s * 1.0e7));
  return mrpt::Clock::fromDouble(start_time_s) + mrpt::Clock::duration(ticks);
}

mrpt::obs::CObservation2DRangeScan::Ptr makeScanObservation(const LaserOptions& laser,
                                                            const SimulatedScan& scan,
                                                            mrpt::Clock::time_point stamp,
                                                            double sigma_m) {
  auto obs = mrpt::obs::CObservation2DRangeScan::Create();
  obs->sensorLabel = laser.label;
  obs->timestamp = stamp;
  obs->aperture = static_cast<float>(degToRad(laser.aperture_deg));
  obs->rightToLeft = true;
  obs->maxRange = static_cast<float>(laser.max_range_m);
  obs->stdError = static_cast<float>(sigma_m);
  obs->sensorPose = toMrpt(laserMountPose(laser));
  obs->resizeScan(scan.ranges_m.size());
  for (std::size_t i = 0; i < scan.ranges_m.size(); ++i) {
    obs->setScanRange(i, scan.ranges_m[i]);
    obs->setScanRangeValidity(i, scan.valid[i] != 0);
  }
  return obs;
}

mrpt::obs::CObservationOdometry::Ptr makeOdometryObservation(const std::string& label,
                                                             const Pose2D& odometry_pose,
                                                             mrpt::Clock::time_point stamp) {
  auto obs = mrpt::obs::CObservationOdometry::Create();
  obs->sensorLabel = label;
  obs->timestamp = stamp;
  obs->odometry = mrpt::poses::CPose2D(odometry_pose.x, odometry_pose.y, odometry_pose.yaw);
  obs->hasEncodersInfo = false;
  obs->hasVelocities = false;
  return obs;
}

mrpt::obs::CActionCollection::Ptr makeOdometryAction(const Pose2D& increment,
                                                     mrpt::Clock::time_point stamp) {
  mrpt::obs::CActionRobotMovement2D::TMotionModelOptions model;
  model.modelSelection = mrpt::obs::CActionRobotMovement2D::mmGaussian;
  // Covers the simulated 2 % distance error and 1 deg/m heading drift. MRPT
  // applies these to the increment in metres and radians: a1 m/m, a2 m/rad,
  // a3 rad/m, a4 rad/rad.
  model.gaussianModel.a1 = 0.03;
  model.gaussianModel.a2 = radToDeg(0.001);
  model.gaussianModel.a3 = degToRad(1.5);
  model.gaussianModel.a4 = 0.05;
  model.gaussianModel.minStdXY = 0.005;
  model.gaussianModel.minStdPHI = degToRad(0.2);
  mrpt::obs::CActionRobotMovement2D movement;
  movement.timestamp = stamp;
  movement.computeFromOdometry(mrpt::poses::CPose2D(increment.x, increment.y, increment.yaw),
                               model);
  auto actions = mrpt::obs::CActionCollection::Create();
  actions->insert(movement);
  return actions;
}

mrpt::obs::CObservationImage::Ptr makeImageObservation(const std::string& label,
                                                       const PinholeIntrinsics& k,
                                                       const Pose6D& camera_pose_on_robot,
                                                       const std::string& file_name,
                                                       mrpt::Clock::time_point stamp) {
  auto obs = mrpt::obs::CObservationImage::Create();
  obs->sensorLabel = label;
  obs->timestamp = stamp;
  obs->cameraPose = toMrpt(camera_pose_on_robot);
  obs->cameraParams.ncols = static_cast<uint32_t>(k.width_px);
  obs->cameraParams.nrows = static_cast<uint32_t>(k.height_px);
  obs->cameraParams.setIntrinsicParamsFromValues(k.fx, k.fy, k.cx, k.cy);
  const auto& d = k.distortion;  // k1 k2 p1 p2 k3
  if (d[0] != 0.0 || d[1] != 0.0 || d[2] != 0.0 || d[3] != 0.0 || d[4] != 0.0) {
    obs->cameraParams.setDistortionPlumbBob(d[0], d[1], d[2], d[3], d[4]);
  } else {
    obs->cameraParams.distortion = mrpt::img::DistortionModel::none;
    obs->cameraParams.dist.fill(0.0);
  }
  obs->cameraParams.cameraName = label;
  obs->image.setExternalStorage(file_name);
  return obs;
}

}  // namespace pmap::sim
