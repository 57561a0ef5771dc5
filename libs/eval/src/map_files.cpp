#include "pmap/eval/map_files.h"

#include "pmap/common/error.h"
#include "pmap/common/ply.h"
#include "pmap/poses/poses_file.h"

namespace pmap::eval {

MapPoints readMapPoints(const std::filesystem::path& ply) {
  const PlyVertices v = readPlyVertices(ply);
  const char* names[] = {"x", "y", "z", "scan", "beam", "surface"};
  int idx[6];
  for (int k = 0; k < 6; ++k) {
    idx[k] = v.find(names[k]);
    if (idx[k] < 0) {
      throw InputError(ply.string() + ": missing vertex property '" + names[k] +
                       "' (not a planar-mapper points.ply?)");
    }
  }
  MapPoints m;
  const size_t n = v.size();
  m.xyz.reserve(n);
  for (size_t i = 0; i < n; ++i) {
    m.xyz.emplace_back(v.columns[idx[0]][i], v.columns[idx[1]][i], v.columns[idx[2]][i]);
    m.scan.push_back(static_cast<int>(v.columns[idx[3]][i]));
    m.beam.push_back(static_cast<int>(v.columns[idx[4]][i]));
    m.surface.push_back(static_cast<int>(v.columns[idx[5]][i]));
  }
  return m;
}

poses::Trajectory readMapPoses(const std::filesystem::path& poses_txt) {
  return poses::readPosesFile(poses_txt);
}

}  // namespace pmap::eval
