// poses.txt: one pose per line, "timestamp x y z yaw pitch roll" (seconds,
// metres, radians; '#' starts a comment line), timestamps strictly
// increasing. Written by planar-mapper and indoor-sim, read by --poses and
// map-eval.
#pragma once

#include <filesystem>

#include "pmap/poses/trajectory.h"

namespace pmap::poses {

/// Reads a poses file. Throws InputError naming file and line for a missing
/// file, a malformed line, a non-finite value or a non-increasing timestamp.
Trajectory readPosesFile(const std::filesystem::path& path);

/// Writes a poses file atomically (throws OutputError).
void writePosesFile(const std::filesystem::path& path, const Trajectory& trajectory);

/// Writes the trajectory in the TUM RGB-D benchmark's format, which
/// trajectory tools (evo, the TUM scripts) read: one pose a line,
/// "timestamp tx ty tz qx qy qz qw" (s, m, unit quaternion), '#' comments.
void writeTumFile(const std::filesystem::path& path, const Trajectory& trajectory);

}  // namespace pmap::poses
