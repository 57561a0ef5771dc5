#include "pmap/poses/poses_file.h"

#include <mrpt/math/CQuaternion.h>
#include <mrpt/poses/CPose3D.h>

#include <cinttypes>
#include <cstdio>
#include <fstream>

#include "pmap/common/atomic_file.h"
#include "pmap/common/error.h"
#include "pmap/common/text.h"

namespace pmap::poses {

Trajectory readPosesFile(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InputError(path.string() + ": poses file not found or not a regular file");
  }
  std::ifstream in(path);
  if (!in) {
    throw InputError(path.string() + ": cannot open poses file");
  }
  Trajectory trajectory;
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') {
      continue;
    }
    const auto where = path.string() + ":" + std::to_string(lineno) + ": ";
    const auto fields = splitFields(t, " \t,");
    if (fields.size() != 7) {
      throw InputError(where + "expected 7 numbers (timestamp x y z yaw pitch roll), got " +
                       std::to_string(fields.size()));
    }
    double v[7];
    for (int i = 0; i < 7; ++i) {
      const auto d = parseDouble(fields[i]);
      if (!d) {
        throw InputError(where + "'" + fields[i] + "' is not a finite number");
      }
      v[i] = *d;
    }
    if (!trajectory.empty() && v[0] <= trajectory.lastTime()) {
      throw InputError(where + "timestamp " + fields[0] + " is not after the previous one");
    }
    trajectory.append(v[0], mrpt::math::TPose3D(v[1], v[2], v[3], v[4], v[5], v[6]));
  }
  if (trajectory.empty()) {
    throw InputError(path.string() + ": no poses in file");
  }
  return trajectory;
}

void writePosesFile(const std::filesystem::path& path, const Trajectory& trajectory) {
  writeFileAtomically(path, [&](std::ostream& out) {
    out << "# timestamp x y z yaw pitch roll (s, m, rad)\n";
    char buf[256];
    for (const auto& p : trajectory.poses()) {
      std::snprintf(buf, sizeof buf, "%.6f %.6f %.6f %.6f %.8f %.8f %.8f\n", p.t, p.pose.x,
                    p.pose.y, p.pose.z, p.pose.yaw, p.pose.pitch, p.pose.roll);
      out << buf;
    }
  });
}

void writeTumFile(const std::filesystem::path& path, const Trajectory& trajectory) {
  writeFileAtomically(path, [&](std::ostream& out) {
    out << "# timestamp tx ty tz qx qy qz qw (TUM format: s, m, unit quaternion)\n";
    char buf[256];
    for (const auto& p : trajectory.poses()) {
      mrpt::math::CQuaternionDouble q;
      mrpt::poses::CPose3D(p.pose).getAsQuaternion(q);
      std::snprintf(buf, sizeof buf, "%.6f %.6f %.6f %.6f %.9f %.9f %.9f %.9f\n", p.t, p.pose.x,
                    p.pose.y, p.pose.z, q.x(), q.y(), q.z(), q.r());
      out << buf;
    }
  });
}

void writeGraphFile(const std::filesystem::path& path, const PoseGraph& graph) {
  std::size_t loops = 0, constraints = 0;
  for (const PoseEdge& e : graph.edges()) {
    constraints += e.path ? 1 : 0;
    loops += e.loop && !e.path ? 1 : 0;
  }
  writeFileAtomically(path, [&](std::ostream& out) {
    out << "# planar-mapper pose graph: " << graph.size() << " keyframes (optimised poses), "
        << graph.edges().size() - loops - constraints << " odometry edges, " << loops
        << " loop closures, " << constraints << " path constraints\n";
    out << "# VERTEX_SE2 id x y theta / EDGE_SE2 from to dx dy dtheta i_xx i_xy i_xt i_yy i_yt "
           "i_tt (m, rad)\n";
    char buf[512];
    for (std::size_t i = 0; i < graph.size(); ++i) {
      const Pose2& p = graph.node(i);
      std::snprintf(buf, sizeof buf, "VERTEX_SE2 %zu %.9g %.9g %.9g\n", i, p.x, p.y, p.theta);
      out << buf;
    }
    for (const PoseEdge& e : graph.edges()) {
      const Eigen::Matrix3d& I = e.information;
      std::snprintf(buf, sizeof buf,
                    "EDGE_SE2 %zu %zu %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g\n", e.from, e.to,
                    e.measurement.x, e.measurement.y, e.measurement.theta, I(0, 0), I(0, 1),
                    I(0, 2), I(1, 1), I(1, 2), I(2, 2));
      out << buf;
    }
  });
}

}  // namespace pmap::poses
