// The sensor labels a rawlog holds, and the check that the configured roles
// ([Sensors]) and --keep-label name labels the file has.
//
// A label that occurs nowhere is the most common configuration mistake
// (`pose_laser = LASER_HORIZ`): without this check the run silently maps
// without that sensor. The check reads the first records only
// (kLabelCheckRecords), so it costs little on any file.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "pmap/input/sensor_roles.h"

namespace pmap::input {

/// The first records read by the label check.
constexpr std::size_t kLabelCheckRecords = 1000;

struct LabelCount {
  std::string class_name;  ///< e.g. "CObservation2DRangeScan"
  std::string label;       ///< "" for unlabelled observations
  std::size_t count = 0;
  std::size_t first_record = 0;
};

struct LabelInventory {
  std::vector<LabelCount> labels;    ///< by first appearance
  std::size_t records = 0;           ///< records read
  std::size_t odometry_actions = 0;  ///< CActionRobotMovement2D (unlabelled odometry)
  bool complete = false;             ///< the whole file was read
  /// Non-empty when reading stopped at bad data (the main pass reports it).
  std::string error;

  /// "LASER_H (CObservation2DRangeScan) x 300, '' (CObservationOdometry) x 2"
  std::string describe() const;
};

/// Reads up to `max_records` records (0: all) of `rawlog` and counts its
/// observations by class and label. Never throws for bad data after the
/// first record (it stops and sets `error`); throws InputError when the file
/// cannot be opened or is not a rawlog.
LabelInventory scanLabels(const std::filesystem::path& rawlog, std::size_t max_records);

/// Which roles the run uses (a role not used is not checked).
struct RolesInUse {
  bool pose_laser = true;
  bool structure = true;
  bool odometry = true;
  bool cameras = true;
};

/// Checks every used role of `sensors` and the `keep_labels` against
/// `inventory`: a role none of whose labels occurs (on a class that can play
/// it) is a ConfigError naming the role, its labels and what the file has;
/// each absent member of a role that has others present gives one warning
/// (returned). The optional roles (odometry, cameras) of a file that has no
/// such sensor at all (a log without cameras) give a warning instead of the
/// error. An empty role (`none`) is not checked. `config_origin` names the
/// ini in messages.
std::vector<std::string> checkRoleLabels(const SensorsOptions& sensors, const RolesInUse& used,
                                         const std::vector<std::string>& keep_labels,
                                         const LabelInventory& inventory,
                                         const std::string& config_origin);

}  // namespace pmap::input
