#include "pmap/input/observation_source.h"

#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/system/datetime.h>

#include <algorithm>
#include <cmath>

#include "pmap/common/error.h"

namespace pmap::input {

const char* toString(RawlogFormat format) {
  switch (format) {
    case RawlogFormat::kObservations:
      return "observations";
    case RawlogFormat::kSensoryFrames:
      return "actions+sensory-frames";
    case RawlogFormat::kMixed:
      return "mixed";
    default:
      return "unknown";
  }
}

namespace {

bool finite(const mrpt::poses::CPose2D& p) {
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.phi());
}

bool finite(const mrpt::poses::CPose3D& p) {
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()) &&
         std::isfinite(p.yaw()) && std::isfinite(p.pitch()) && std::isfinite(p.roll());
}

// The poses the pose stage would use: the sensor pose, and an odometry
// reading. One NaN there makes MRPT's ICP estimate NaN for the rest of the
// run (and every point placed after it).
bool finitePoses(const mrpt::obs::CObservation& obs) {
  mrpt::poses::CPose3D sensor;
  obs.getSensorPose(sensor);
  if (!finite(sensor)) {
    return false;
  }
  const auto* odometry = dynamic_cast<const mrpt::obs::CObservationOdometry*>(&obs);
  return odometry == nullptr || finite(odometry->odometry);
}

// An odometry action whose increment is NaN / Inf (sf format).
bool finiteAction(const mrpt::obs::CActionCollection& actions) {
  for (const auto& a : actions) {
    const auto* move = dynamic_cast<const mrpt::obs::CActionRobotMovement2D*>(a.get());
    if (move != nullptr && !finite(move->rawOdometryIncrementReading)) {
      return false;
    }
  }
  return true;
}

}  // namespace

bool SelectionOptions::validate(std::string* why) const {
  if (from_index > to_index) {
    *why = "--from-index (" + std::to_string(from_index) + ") is after --to-index (" +
           std::to_string(to_index) + ")";
    return false;
  }
  if (decimate == 0) {
    *why = "--decimate must be >= 1";
    return false;
  }
  return true;
}

ObservationSource::ObservationSource(RawlogReader& reader, RoleClassifier classifier,
                                     SelectionOptions selection)
    : reader_(reader), classifier_(std::move(classifier)), selection_(std::move(selection)) {}

void ObservationSource::noteFormat(RawlogFormat f) {
  if (stats_.format == RawlogFormat::kUnknown) {
    stats_.format = f;
  } else if (stats_.format != f) {
    stats_.format = RawlogFormat::kMixed;
  }
}

// [Sensors] pose_laser_aperture_deg: the field of view the scan is taken
// with, where the log's is wrong (doc/input.md, "Scan aperture").
void ObservationSource::replaceAperture(mrpt::obs::CObservation& obs) {
  const double deg = classifier_.options().pose_laser_aperture_deg;
  auto* scan = dynamic_cast<mrpt::obs::CObservation2DRangeScan*>(&obs);
  if (deg <= 0.0 || scan == nullptr) {
    return;
  }
  if (stats_.aperture_replaced++ == 0) {
    stats_.file_aperture_deg = scan->aperture * 180.0 / M_PI;
    stats_.used_aperture_deg = deg;
  }
  scan->aperture = static_cast<float>(deg * M_PI / 180.0);
}

void ObservationSource::addObservation(const mrpt::obs::CObservation::Ptr& obs, bool selected,
                                       InputStep& step) {
  ++stats_.observations;
  ObservationItem item;
  item.obs = obs;
  item.roles = classifier_.classify(*obs);
  if (item.roles.structure) {
    item.structure_index = next_structure_index_++;
  }
  const auto& keep = selection_.keep_labels;
  if (!keep.empty() && std::find(keep.begin(), keep.end(), obs->sensorLabel) == keep.end()) {
    selected = false;
  }
  if (!selected) {
    return;
  }
  if (!item.roles.any()) {
    ++stats_.ignored[std::string(obs->GetRuntimeClass()->className) + ":" + obs->sensorLabel];
    return;
  }
  if (obs->timestamp == INVALID_TIMESTAMP) {
    ++stats_.invalid_timestamps;
    return;
  }
  if ((item.roles.odometry || item.roles.pose_laser) && !finitePoses(*obs)) {
    ++stats_.non_finite_poses;  // not for the poses; a structure scan is checked when extracted
    item.roles.odometry = false;
    item.roles.pose_laser = false;
    if (!item.roles.any()) {
      return;
    }
  }
  if (item.roles.structure &&
      item.structure_index % static_cast<std::int64_t>(selection_.decimate) != 0) {
    item.roles.structure = false;
    ++stats_.structure_decimated;
    if (!item.roles.any()) {
      return;
    }
  }
  if (item.roles.pose_laser) {
    replaceAperture(*obs);
  }
  stats_.pose_scans += item.roles.pose_laser ? 1 : 0;
  stats_.structure_scans += item.roles.structure ? 1 : 0;
  stats_.odometry += item.roles.odometry ? 1 : 0;
  stats_.images += item.roles.camera ? 1 : 0;
  step.observations.push_back(std::move(item));
}

bool ObservationSource::next(InputStep& step) {
  using namespace mrpt::obs;
  RawlogRecord record;
  while (reader_.next(record)) {
    ++stats_.records;
    const bool in_range =
        record.index >= selection_.from_index && record.index <= selection_.to_index;
    step = InputStep{};
    step.record = record.index;
    step.offset = record.offset;
    if (auto action = std::dynamic_pointer_cast<CActionCollection>(record.object)) {
      noteFormat(RawlogFormat::kSensoryFrames);
      seen_action_ = true;
      pending_action_ = in_range ? action : nullptr;
      if (pending_action_ && !finiteAction(*action)) {
        ++stats_.non_finite_poses;
        pending_action_.reset();
      }
      continue;
    }
    if (auto sf = std::dynamic_pointer_cast<CSensoryFrame>(record.object)) {
      noteFormat(RawlogFormat::kSensoryFrames);
      step.sensory_frame = true;
      step.action = std::move(pending_action_);
      pending_action_.reset();
      bool selected = in_range;
      if (!seen_action_ && selection_.skip_leading_frame) {
        selected = false;
        stats_.leading_frame_skipped = true;
      }
      for (const auto& obs : *sf) {
        if (obs) {
          addObservation(obs, selected, step);
        }
      }
    } else if (auto obs = std::dynamic_pointer_cast<CObservation>(record.object)) {
      noteFormat(RawlogFormat::kObservations);
      addObservation(obs, in_range, step);
    } else {
      throw InputError(reader_.path().string() + ": record " + std::to_string(record.index) +
                       " at byte " + std::to_string(record.offset) + ": unsupported object '" +
                       record.object->GetRuntimeClass()->className +
                       "' (expected observations, actions or sensory frames)");
    }
    if (!in_range && record.index > selection_.to_index) {
      return false;
    }
    if (!step.observations.empty() || step.action) {
      return true;
    }
  }
  return false;
}

}  // namespace pmap::input
