// Small synthetic rawlogs written with MRPT's own serialization, for unit
// tests of the reader, the roles and the pose stage.
#pragma once

#include <filesystem>
#include <string>

namespace pmap::testing {

enum class FixtureFormat { kObservations, kSensoryFrames };

/// What the vertical (structure) scans return.
enum class StructureRanges {
  kCorridor,    ///< the ideal walls and ceiling
  kAllInvalid,  ///< every beam flagged invalid
  kNanValid,    ///< every 7th beam NaN / +Inf but flagged valid
  kNegative,    ///< every 5th beam 0 or negative, flagged valid
  kScattered,   ///< valid ranges at random: nothing planar to find
};

/// Damage to the observations' timestamps (odometry and both lasers).
enum class TimestampFault {
  kNone,
  kZero,       ///< every 4th cycle has timestamp 0 (INVALID_TIMESTAMP)
  kDuplicate,  ///< every 4th cycle repeats the previous cycle's timestamps
  kBackwards,  ///< every 4th cycle lies 1 s before the previous one
};

struct FixtureOptions {
  FixtureFormat format = FixtureFormat::kObservations;
  bool gzip = true;
  int cycles = 20;             ///< 5 Hz cycles: odometry + LASER_H (+ LASER_V)
  bool vertical = true;        ///< add a LASER_V scan per cycle
  bool leading_frame = false;  ///< sf format: start with a frame without action
  double speed_mps = 0.4;
  StructureRanges ranges = StructureRanges::kCorridor;
  TimestampFault timestamps = TimestampFault::kNone;
  bool nan_odometry = false;  ///< cycle 5's odometry reading is (NaN, NaN, NaN)
  double offset_x_m = 0.0;    ///< odometry starts here (e.g. 1e6: far from the origin)
  std::string laser_v_label = "LASER_V";
};

/// Writes a rawlog of a robot driving +x along a 4 m wide corridor whose
/// walls are at y = +-2, an end wall at x = 6 and the ceiling at z = 2.5: ideal
/// ranges, no noise.
void writeFixtureRawlog(const std::filesystem::path& path, const FixtureOptions& options);

/// A fresh, empty directory under the test build tree.
std::filesystem::path freshTestDir(const std::string& name);

/// Copies the first `fraction` of `src`'s bytes to `dst`.
void truncateCopy(const std::filesystem::path& src, const std::filesystem::path& dst,
                  double fraction);

}  // namespace pmap::testing
