#include "pmap/poses/icp_pose_tracker.h"

#include <mrpt/maps/CPointsMap.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/slam/CMetricMapBuilderICP.h>
#include <mrpt/system/datetime.h>

namespace pmap::poses {

class IcpPoseTracker::Impl {
 public:
  mrpt::slam::CMetricMapBuilderICP builder;
};

IcpPoseTracker::IcpPoseTracker(const mrpt::config::CConfigFileBase& config)
    : impl_(std::make_unique<Impl>()) {
  auto& b = impl_->builder;
  b.setVerbosityLevel(mrpt::system::LVL_ERROR);
  b.ICP_options.loadFromConfigFile(config, "MappingApplication");
  b.ICP_params.loadFromConfigFile(config, "ICP");
  b.options.alwaysInsertByClass.fromString(
      config.read_string("MappingApplication", "alwaysInsertByClass", ""));
  b.initialize();
}

IcpPoseTracker::~IcpPoseTracker() = default;

mrpt::math::TPose3D IcpPoseTracker::currentPose() const {
  return impl_->builder.getCurrentPoseEstimation()->getMeanVal().asTPose();
}

void IcpPoseTracker::recordPose(double t) {
  if (!trajectory_.append(t, currentPose())) {
    ++stats_.non_monotonic;
  }
}

void IcpPoseTracker::replaceMap(const std::vector<Eigen::Vector2d>& points) {
  const auto map =
      impl_->builder.getCurrentlyBuiltMetricMap()->mapByClass<mrpt::maps::CPointsMap>();
  if (!map) {
    return;
  }
  map->clear();
  map->reserve(points.size());
  for (const Eigen::Vector2d& p : points) {
    map->insertPointFast(static_cast<float>(p.x()), static_cast<float>(p.y()), 0.0f);
  }
  map->mark_as_modified();  // its kd-tree is built again when next matched against
}

void IcpPoseTracker::clipMap(double x, double y, double radius_m) {
  const auto map =
      impl_->builder.getCurrentlyBuiltMetricMap()->mapByClass<mrpt::maps::CPointsMap>();
  if (map) {
    map->clipOutOfRange(mrpt::math::TPoint2D(x, y), static_cast<float>(radius_m));
  }
}

void IcpPoseTracker::processObservation(const mrpt::obs::CObservation::Ptr& obs, bool is_odometry) {
  impl_->builder.processObservation(obs);
  if (is_odometry) {
    ++stats_.odometry_readings;
  } else {
    ++stats_.scans_matched;
  }
  recordPose(mrpt::Clock::toDouble(obs->timestamp));
}

void IcpPoseTracker::processFrame(const mrpt::obs::CActionCollection::Ptr& action,
                                  const std::vector<mrpt::obs::CObservation::Ptr>& observations) {
  mrpt::obs::CActionCollection empty_action;
  mrpt::obs::CSensoryFrame frame;
  double last_t = -1;
  for (const auto& obs : observations) {
    frame.insert(obs);
    last_t = std::max(last_t, mrpt::Clock::toDouble(obs->timestamp));
    const bool odo = IS_CLASS(*obs, mrpt::obs::CObservationOdometry);
    ++(odo ? stats_.odometry_readings : stats_.scans_matched);
  }
  double action_t = -1;
  if (action) {
    if (const auto move = action->getBestMovementEstimation()) {
      action_t = mrpt::Clock::toDouble(move->timestamp);
      ++stats_.odometry_readings;
    }
  }
  impl_->builder.processActionObservation(action ? *action : empty_action, frame);
  const double t = std::max(last_t, action_t);
  if (t > 0) {
    recordPose(t);
  }
}

}  // namespace pmap::poses
