// Small synthetic rawlogs written with MRPT's own serialization, for unit
// tests of the reader, the roles and the pose stage.
#pragma once

#include <filesystem>
#include <string>

namespace pmap::testing {

enum class FixtureFormat { kObservations, kSensoryFrames };

struct FixtureOptions {
  FixtureFormat format = FixtureFormat::kObservations;
  bool gzip = true;
  int cycles = 20;             ///< 5 Hz cycles: odometry + LASER_H (+ LASER_V)
  bool vertical = true;        ///< add a LASER_V scan per cycle
  bool leading_frame = false;  ///< sf format: start with a frame without action
  double speed_mps = 0.4;
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
