#include "pmap/input/ply_cloud.h"

#include "pmap/common/error.h"
#include "pmap/common/ply.h"

namespace pmap::input {

StructureScan readPlyCloud(const std::filesystem::path& path) {
  const PlyVertices v = readPlyVertices(path);
  const int ix = v.find("x");
  const int iy = v.find("y");
  const int iz = v.find("z");
  if (ix < 0 || iy < 0 || iz < 0) {
    throw InputError(path.string() + ": PLY vertices lack x, y or z");
  }
  StructureScan scan;
  scan.index = 0;
  scan.label = "cloud";
  scan.organised = false;
  scan.cols = static_cast<int>(v.size());
  scan.points.reserve(v.size());
  for (size_t i = 0; i < v.size(); ++i) {
    const Eigen::Vector3d p(v.columns[ix][i], v.columns[iy][i], v.columns[iz][i]);
    if (!p.allFinite()) {
      ++scan.dropped.non_finite;
      continue;
    }
    scan.points.push_back(p);
    scan.beams.push_back(static_cast<std::int32_t>(i));
  }
  return scan;
}

}  // namespace pmap::input
