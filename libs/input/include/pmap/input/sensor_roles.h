// [Sensors]: which observation plays which role, by sensor label.
//
//   [Sensors]
//   pose_laser = LASER_H                  ; horizontal 2D laser(s) for ICP poses
//   structure  = LASER_V                  ; 2D scans, 3D range, Velodyne, point clouds
//   odometry   = ODOMETRY                 ; CObservationOdometry labels
//   cameras    = CAMERA_LEFT, CAMERA_RIGHT
//
// Each value is a comma-separated list of labels. An empty label (an empty
// value, or an empty item as in "A, ") matches unlabelled observations (MRPT's
// shipped logs have none). The single word `none` assigns no sensor to the
// role. max_pose_gap_s bounds pose interpolation. Odometry actions of the actions/sensory-frames
// format (CActionRobotMovement2D) carry no label and are always odometry.
// pose_laser_aperture_deg replaces the field of view the log gives its
// pose-laser scans (CObservation2DRangeScan::aperture), for logs converted
// with a wrong one (doc/input.md, "Scan aperture").
#pragma once

#include <mrpt/obs/CObservation.h>

#include <string>
#include <vector>

namespace pmap::config {
class SectionReader;
}

namespace pmap::input {

struct SensorsOptions {
  std::vector<std::string> pose_laser = {"LASER_H"};
  std::vector<std::string> structure = {"LASER_V"};
  std::vector<std::string> odometry = {"ODOMETRY"};
  std::vector<std::string> cameras = {"CAMERA_LEFT", "CAMERA_RIGHT"};
  /// Longest interval between two poses across which a structure scan's pose
  /// is interpolated (s); scans in longer gaps are dropped and counted.
  double max_pose_gap_s = 1.0;
  /// The pose laser's field of view, first to last beam (deg); 0 keeps the
  /// aperture each scan carries.
  double pose_laser_aperture_deg = 0.0;

  void load(config::SectionReader& reader);
  bool validate(std::string* why) const;
};

/// The roles one observation plays (a 2D scan may be both pose laser and
/// structure sensor).
struct Roles {
  bool pose_laser = false;
  bool structure = false;
  bool odometry = false;
  bool camera = false;
  bool any() const { return pose_laser || structure || odometry || camera; }
};

class RoleClassifier {
 public:
  explicit RoleClassifier(SensorsOptions options) : options_(std::move(options)) {}
  /// Roles by label and class: pose laser = CObservation2DRangeScan;
  /// structure = CObservation2DRangeScan, CObservation3DRangeScan,
  /// CObservationVelodyneScan, CObservationPointCloud; odometry =
  /// CObservationOdometry; camera = CObservationImage.
  Roles classify(const mrpt::obs::CObservation& obs) const;
  const SensorsOptions& options() const { return options_; }

 private:
  SensorsOptions options_;
};

/// True for the observation classes that can be structure sensors.
bool isStructureClass(const mrpt::obs::CObservation& obs);

}  // namespace pmap::input
