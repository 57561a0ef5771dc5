// Turns rawlog records into input steps: observations with their roles,
// selected as rawlog-edit names it (--from-index, --to-index, --keep-label)
// plus structure-scan decimation.
//
// One step per record in the observations-only format; one step per sensory
// frame (with the action before it) in the actions + sensory-frames format.
// Structure observations are numbered in file order ("structure scan index",
// the key of gt.json and points.ply) before any selection, so an index means
// the same scan whatever is selected.
#pragma once

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservation.h>

#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "pmap/input/rawlog_reader.h"
#include "pmap/input/sensor_roles.h"

namespace pmap::input {

struct SelectionOptions {
  /// First and last record index to use (inclusive), as rawlog-edit's
  /// --from-index / --to-index.
  std::size_t from_index = 0;
  std::size_t to_index = std::numeric_limits<std::size_t>::max();
  /// Keep only observations with these labels (empty: keep all).
  std::vector<std::string> keep_labels;
  /// Use every N-th structure scan (by structure scan index).
  std::size_t decimate = 1;
  /// Drop a sensory frame that has no action before it, as MRPT's pair
  /// reader (and so icp-slam) does.
  bool skip_leading_frame = false;

  bool validate(std::string* why) const;
};

struct ObservationItem {
  mrpt::obs::CObservation::Ptr obs;
  Roles roles;
  /// Index among all structure observations in the file; -1 if not structure.
  std::int64_t structure_index = -1;
};

struct InputStep {
  std::size_t record = 0;      ///< record index of the observation / sensory frame
  std::uint64_t offset = 0;    ///< its uncompressed byte offset
  bool sensory_frame = false;  ///< actions + sensory-frames format
  /// The odometry action before this frame (sf format), may be null.
  mrpt::obs::CActionCollection::Ptr action;
  /// Selected observations that play at least one role, in record order.
  std::vector<ObservationItem> observations;
};

enum class RawlogFormat { kUnknown, kObservations, kSensoryFrames, kMixed };
const char* toString(RawlogFormat format);

struct InputStats {
  RawlogFormat format = RawlogFormat::kUnknown;
  std::size_t records = 0;
  std::size_t observations = 0;  ///< all observations seen (selected or not)
  std::size_t pose_scans = 0;    ///< selected, by role
  std::size_t structure_scans = 0;
  std::size_t odometry = 0;
  std::size_t images = 0;
  std::size_t structure_decimated = 0;
  std::size_t invalid_timestamps = 0;  ///< observations dropped: no timestamp
  /// Odometry readings / actions and pose-laser scans not used for the
  /// poses: a NaN or Inf in the odometry or the sensor pose.
  std::size_t non_finite_poses = 0;
  /// Pose-laser scans whose aperture [Sensors] pose_laser_aperture_deg
  /// replaced, and the aperture the first of them carried (deg).
  std::size_t aperture_replaced = 0;
  double file_aperture_deg = 0.0;
  double used_aperture_deg = 0.0;
  bool leading_frame_skipped = false;
  /// Observations that play no role, by "Class:label".
  std::map<std::string, std::size_t> ignored;
};

class ObservationSource {
 public:
  ObservationSource(RawlogReader& reader, RoleClassifier classifier, SelectionOptions selection);

  /// Fills the next step; false at the end of the selection.
  bool next(InputStep& step);
  const InputStats& stats() const { return stats_; }
  const RawlogReader& reader() const { return reader_; }

 private:
  void noteFormat(RawlogFormat f);
  void addObservation(const mrpt::obs::CObservation::Ptr& obs, bool selected, InputStep& step);
  void replaceAperture(mrpt::obs::CObservation& obs);

  RawlogReader& reader_;
  RoleClassifier classifier_;
  SelectionOptions selection_;
  InputStats stats_;
  std::int64_t next_structure_index_ = 0;
  mrpt::obs::CActionCollection::Ptr pending_action_;
  bool seen_action_ = false;
};

}  // namespace pmap::input
