#include "pmap/input/label_inventory.h"

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <algorithm>

#include "pmap/common/error.h"
#include "pmap/input/rawlog_reader.h"

namespace pmap::input {
namespace {

std::string shortClass(const std::string& name) {
  const auto colon = name.rfind(':');
  return colon == std::string::npos ? name : name.substr(colon + 1);
}

void count(LabelInventory& inv, const mrpt::obs::CObservation& obs, std::size_t record) {
  const std::string cls = shortClass(obs.GetRuntimeClass()->className);
  for (LabelCount& c : inv.labels) {
    if (c.class_name == cls && c.label == obs.sensorLabel) {
      ++c.count;
      return;
    }
  }
  inv.labels.push_back({cls, obs.sensorLabel, 1, record});
}

void countRecord(LabelInventory& inv, const RawlogRecord& record) {
  using namespace mrpt::obs;
  if (const auto actions = std::dynamic_pointer_cast<CActionCollection>(record.object)) {
    for (const auto& a : *actions) {
      inv.odometry_actions += IS_CLASS(*a, CActionRobotMovement2D) ? 1 : 0;
    }
  } else if (const auto sf = std::dynamic_pointer_cast<CSensoryFrame>(record.object)) {
    for (const auto& obs : *sf) {
      if (obs) {
        count(inv, *obs, record.index);
      }
    }
  } else if (const auto obs = std::dynamic_pointer_cast<CObservation>(record.object)) {
    count(inv, *obs, record.index);
  }
}

// The classes that can play a role (sensor_roles.h).
bool canPlay(const std::string& role, const std::string& cls) {
  if (role == "pose_laser") {
    return cls == "CObservation2DRangeScan";
  }
  if (role == "structure") {
    return cls == "CObservation2DRangeScan" || cls == "CObservation3DRangeScan" ||
           cls == "CObservationVelodyneScan" || cls == "CObservationPointCloud";
  }
  if (role == "odometry") {
    return cls == "CObservationOdometry";
  }
  if (role == "cameras") {
    return cls == "CObservationImage";
  }
  return true;  // --keep-label: any class
}

bool present(const LabelInventory& inv, const std::string& role, const std::string& label) {
  return std::any_of(inv.labels.begin(), inv.labels.end(), [&](const LabelCount& c) {
    return c.label == label && canPlay(role, c.class_name);
  });
}

std::string quoted(const std::string& label) {
  return label.empty() ? "'' (unlabelled)" : "'" + label + "'";
}

std::string joined(const std::vector<std::string>& labels) {
  std::string out;
  for (const std::string& l : labels) {
    out += (out.empty() ? "" : ", ") + l;
  }
  return out;
}

// True when the file has observations of a class that can play `role`.
bool hasClassFor(const LabelInventory& inv, const std::string& role) {
  return std::any_of(inv.labels.begin(), inv.labels.end(),
                     [&](const LabelCount& c) { return canPlay(role, c.class_name); });
}

// Checks one role: throws when none of `labels` is present, returns one
// warning per absent member otherwise. An optional role (odometry, cameras)
// whose kind of sensor the file does not have at all is not a wrong label:
// one warning says what the run goes without.
void checkRole(const std::string& role, const std::string& setting,
               const std::vector<std::string>& labels, const LabelInventory& inv,
               const std::string& where, std::vector<std::string>& warnings) {
  std::vector<std::string> absent;
  for (const std::string& l : labels) {
    if (!present(inv, role, l)) {
      absent.push_back(l);
    }
  }
  const std::string scope = "the first " + std::to_string(inv.records) + " records";
  const bool optional = role == "odometry" || role == "cameras";
  if (absent.size() == labels.size() && optional && !hasClassFor(inv, role)) {
    warnings.push_back(setting + " = " + joined(labels) + ": the rawlog has no " +
                       (role == "cameras" ? "camera images (the map is untextured)"
                                          : "odometry (poses from the laser alone)") +
                       " in " + scope);
    return;
  }
  if (absent.size() == labels.size()) {
    throw ConfigError(where + setting + " = " + joined(labels) + ": no " +
                      (role == "--keep-label" ? std::string("observation") : "usable " + role) +
                      " observation with " + (labels.size() > 1 ? "these labels" : "this label") +
                      " in " + scope + " of the rawlog; it has: " + inv.describe() +
                      " (planar-mapper --list-labels lists the whole file)");
  }
  for (const std::string& l : absent) {
    warnings.push_back(setting + ": no observation labelled " + quoted(l) + " in " + scope +
                       " (the role keeps its other labels)");
  }
}

}  // namespace

std::string LabelInventory::describe() const {
  if (labels.empty() && odometry_actions == 0) {
    return "no observations";
  }
  std::string out;
  for (const LabelCount& c : labels) {
    out += (out.empty() ? "" : ", ") + quoted(c.label) + " (" + c.class_name + ") x " +
           std::to_string(c.count);
  }
  if (odometry_actions > 0) {
    out += (out.empty() ? "" : ", ") + std::string("odometry actions (CActionRobotMovement2D) x ") +
           std::to_string(odometry_actions);
  }
  return out;
}

LabelInventory scanLabels(const std::filesystem::path& rawlog, std::size_t max_records) {
  RawlogReaderOptions options;
  options.accept_truncated = true;
  RawlogReader reader(rawlog, options);
  LabelInventory inv;
  RawlogRecord record;
  try {
    while ((max_records == 0 || inv.records < max_records) && reader.next(record)) {
      ++inv.records;
      countRecord(inv, record);
    }
    inv.complete = max_records == 0 || inv.records < max_records;
  } catch (const InputError& e) {
    if (inv.records == 0 && std::string(e.what()).find("not a rawlog") != std::string::npos) {
      throw;
    }
    inv.error = e.what();
  }
  return inv;
}

std::vector<std::string> checkRoleLabels(const SensorsOptions& sensors, const RolesInUse& used,
                                         const std::vector<std::string>& keep_labels,
                                         const LabelInventory& inventory,
                                         const std::string& config_origin) {
  std::vector<std::string> warnings;
  if (!inventory.error.empty()) {
    return warnings;  // the main pass reports the bad data
  }
  const std::string where = config_origin + ": ";
  const struct {
    const char* role;
    bool use;
    const std::vector<std::string>& labels;
  } roles[] = {{"pose_laser", used.pose_laser, sensors.pose_laser},
               {"structure", used.structure, sensors.structure},
               {"odometry", used.odometry && inventory.odometry_actions == 0, sensors.odometry},
               {"cameras", used.cameras, sensors.cameras}};
  for (const auto& r : roles) {
    if (r.use && !r.labels.empty()) {
      checkRole(r.role, std::string("[Sensors] ") + r.role, r.labels, inventory, where, warnings);
    }
  }
  if (!keep_labels.empty()) {
    checkRole("--keep-label", "--keep-label", keep_labels, inventory, "", warnings);
  }
  return warnings;
}

}  // namespace pmap::input
