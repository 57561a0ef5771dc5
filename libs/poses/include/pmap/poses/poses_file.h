// poses.txt: one pose per line, "timestamp x y z yaw pitch roll" (seconds,
// metres, radians; '#' starts a comment line), timestamps strictly
// increasing. Written by planar-mapper and indoor-sim, read by --poses and
// map-eval.
#pragma once

#include <filesystem>

#include "pmap/poses/pose_graph.h"
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

/// Writes a pose graph in the text format MRPT's graph tools read and write
/// (mrpt::graphs::CNetworkOfPoses2DInf::loadFromTextFile, g2o's 2D lines):
///   VERTEX_SE2 id x y theta
///   EDGE_SE2 from to dx dy dtheta i_xx i_xy i_xt i_yy i_yt i_tt
/// (m, rad; the information's upper triangle), after '#' comment lines.
void writeGraphFile(const std::filesystem::path& path, const PoseGraph& graph);

}  // namespace pmap::poses
