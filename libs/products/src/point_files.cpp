#include "pmap/products/point_files.h"

#include <mrpt/math/CQuaternion.h>
#include <mrpt/poses/CPose3D.h>

#include <cstdio>

#include "pmap/common/atomic_file.h"
#include "pmap/common/ply.h"

namespace pmap::products {

void writePointsPly(const std::filesystem::path& path, const points::PointMap& map,
                    const std::vector<int>& surface_ids) {
  const size_t n = map.size();
  std::vector<double> x(n), y(n), z(n), scan(n), beam(n), surface(n, -1.0);
  for (size_t i = 0; i < n; ++i) {
    x[i] = map.xyz()[i].x();
    y[i] = map.xyz()[i].y();
    z[i] = map.xyz()[i].z();
    scan[i] = map.scanIndex()[i];
    beam[i] = map.beamIndex()[i];
    if (i < surface_ids.size()) {
      surface[i] = surface_ids[i];
    }
  }
  writePlyVertices(path,
                   {{"x", "float", &x},
                    {"y", "float", &y},
                    {"z", "float", &z},
                    {"scan", "int", &scan},
                    {"beam", "int", &beam},
                    {"surface", "int", &surface}},
                   {"planar-mapper points: scan = structure scan index in the file, "
                    "surface = -1 for no surface"});
}

void writeScansCsv(const std::filesystem::path& path, const points::PointMap& map) {
  writeFileAtomically(path, [&](std::ostream& out) {
    out << "scan,timestamp,label,x,y,z,qw,qx,qy,qz,robot_x,robot_y,robot_yaw,points\n";
    char buf[512];
    for (const auto& s : map.scans()) {
      mrpt::math::CQuaternionDouble q;
      mrpt::poses::CPose3D(s.sensor_pose).getAsQuaternion(q);
      std::snprintf(buf, sizeof buf,
                    "%lld,%.6f,%s,%.6f,%.6f,%.6f,%.9f,%.9f,%.9f,%.9f,%.6f,%.6f,%.8f,%zu\n",
                    static_cast<long long>(s.index), s.timestamp, s.label.c_str(), s.sensor_pose.x,
                    s.sensor_pose.y, s.sensor_pose.z, q.r(), q.x(), q.y(), q.z(), s.robot_pose.x,
                    s.robot_pose.y, s.robot_pose.yaw, s.num_points);
      out << buf;
    }
  });
}

}  // namespace pmap::products
