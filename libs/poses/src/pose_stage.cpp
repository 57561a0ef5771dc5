#include "pmap/poses/pose_stage.h"

#include "pmap/common/error.h"
#include "pmap/common/text.h"

namespace pmap::poses {

PoseStage::PoseStage(std::unique_ptr<IcpPoseTracker> tracker) : tracker_(std::move(tracker)) {}

PoseStage::PoseStage(Trajectory given) : given_(std::move(given)) {}

const Trajectory& PoseStage::trajectory() const {
  return tracker_ ? tracker_->trajectory() : given_;
}

void PoseStage::process(const input::InputStep& step, const std::string& file) {
  if (!tracker_) {
    return;
  }
  try {
    if (step.sensory_frame) {
      std::vector<mrpt::obs::CObservation::Ptr> for_icp;
      for (const auto& item : step.observations) {
        if (item.roles.pose_laser || item.roles.odometry) {
          for_icp.push_back(item.obs);
        }
      }
      if (!for_icp.empty() || step.action) {
        tracker_->processFrame(step.action, for_icp);
      }
      return;
    }
    for (const auto& item : step.observations) {
      if (item.roles.odometry || item.roles.pose_laser) {
        tracker_->processObservation(item.obs, item.roles.odometry);
      }
    }
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(file + ": record " + std::to_string(step.record) + " at byte " +
                     std::to_string(step.offset) +
                     ": rejected by the ICP pose stage: " + oneLineError(e.what()));
  }
}

}  // namespace pmap::poses
