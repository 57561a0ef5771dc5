#include "pmap/input/sensor_roles.h"

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationVelodyneScan.h>

#include <algorithm>

#include "pmap/config/section_reader.h"

namespace pmap::input {
namespace {

// "none" (alone) clears the role.
void readRole(config::SectionReader& reader, const std::string& key,
              std::vector<std::string>& labels) {
  reader.read(key, labels);
  if (labels.size() == 1 && labels[0] == "none") {
    labels.clear();
  }
}

bool matches(const std::vector<std::string>& labels, const std::string& label) {
  return std::find(labels.begin(), labels.end(), label) != labels.end();
}

}  // namespace

void SensorsOptions::load(config::SectionReader& reader) {
  readRole(reader, "pose_laser", pose_laser);
  readRole(reader, "structure", structure);
  readRole(reader, "odometry", odometry);
  readRole(reader, "cameras", cameras);
  reader.read("max_pose_gap_s", max_pose_gap_s);
  reader.read("pose_laser_aperture_deg", pose_laser_aperture_deg);
}

bool SensorsOptions::validate(std::string* why) const {
  for (const auto* list : {&pose_laser, &structure, &odometry, &cameras}) {
    if (std::count(list->begin(), list->end(), "none") > 0) {
      *why = "'none' must be the only item of a role list";
      return false;
    }
  }
  if (!(max_pose_gap_s > 0.0)) {
    *why = "max_pose_gap_s must be > 0 seconds";
    return false;
  }
  if (!(pose_laser_aperture_deg >= 0.0 && pose_laser_aperture_deg <= 360.0)) {
    *why = "pose_laser_aperture_deg must be in [0, 360] degrees (0: the scans' own)";
    return false;
  }
  if (pose_laser.empty() && structure.empty()) {
    *why = "pose_laser and structure are both 'none': nothing to do";
    return false;
  }
  return true;
}

bool isStructureClass(const mrpt::obs::CObservation& obs) {
  using namespace mrpt::obs;
  return IS_CLASS(obs, CObservation2DRangeScan) || IS_CLASS(obs, CObservation3DRangeScan) ||
         IS_CLASS(obs, CObservationVelodyneScan) || IS_CLASS(obs, CObservationPointCloud);
}

Roles RoleClassifier::classify(const mrpt::obs::CObservation& obs) const {
  using namespace mrpt::obs;
  const std::string& label = obs.sensorLabel;
  Roles r;
  r.pose_laser = IS_CLASS(obs, CObservation2DRangeScan) && matches(options_.pose_laser, label);
  r.structure = isStructureClass(obs) && matches(options_.structure, label);
  r.odometry = IS_CLASS(obs, CObservationOdometry) && matches(options_.odometry, label);
  r.camera = IS_CLASS(obs, CObservationImage) && matches(options_.cameras, label);
  return r;
}

}  // namespace pmap::input
