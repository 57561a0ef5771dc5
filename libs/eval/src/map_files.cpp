#include "pmap/eval/map_files.h"

#include <cmath>
#include <limits>
#include <system_error>

#include "pmap/common/error.h"
#include "pmap/common/ply.h"
#include "pmap/poses/poses_file.h"

namespace pmap::eval {
namespace {

const char* const kPointProperties[] = {"x", "y", "z", "scan", "beam", "surface"};

std::string valueText(double v) {
  return std::isnan(v) ? "nan" : v > 0 ? "inf" : "-inf";
}

/// Value k (0-2: coordinates, 3-5: integers) of a vertex, checked.
double checkedValue(const PlyVertices& v, int column, int k, std::size_t vertex,
                    const std::filesystem::path& ply) {
  const double value = v.columns[column][vertex];
  const auto fail = [&](const std::string& what) {
    throw InputError(ply.string() + ": vertex " + std::to_string(vertex) + ": " +
                     kPointProperties[k] + " " + what);
  };
  if (!std::isfinite(value)) {
    fail("is " + valueText(value) + ", not a finite number");
  }
  if (k >= 3 && (value != std::floor(value) || value < std::numeric_limits<int>::min() ||
                 value > std::numeric_limits<int>::max())) {
    fail(std::to_string(value) + " is not an integer in int range");
  }
  return value;
}

}  // namespace

void requireRegularFile(const std::filesystem::path& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (std::filesystem::is_regular_file(status)) {
    return;
  }
  if (std::filesystem::is_directory(status)) {
    throw InputError(path.string() + ": is a directory, not a file");
  }
  if (!std::filesystem::exists(status)) {
    throw InputError(path.string() + ": not found");
  }
  throw InputError(path.string() + ": not a regular file");
}

MapPoints readMapPoints(const std::filesystem::path& ply) {
  const PlyVertices v = readPlyVertices(ply);
  int idx[6];
  for (int k = 0; k < 6; ++k) {
    idx[k] = v.find(kPointProperties[k]);
    if (idx[k] < 0) {
      throw InputError(ply.string() + ": missing vertex property '" + kPointProperties[k] +
                       "' (not a planar-mapper points.ply?)");
    }
  }
  MapPoints m;
  const size_t n = v.size();
  m.xyz.reserve(n);
  for (size_t i = 0; i < n; ++i) {
    double value[6];
    for (int k = 0; k < 6; ++k) {
      value[k] = checkedValue(v, idx[k], k, i, ply);
    }
    m.xyz.emplace_back(value[0], value[1], value[2]);
    m.scan.push_back(static_cast<int>(value[3]));
    m.beam.push_back(static_cast<int>(value[4]));
    m.surface.push_back(static_cast<int>(value[5]));
  }
  return m;
}

poses::Trajectory readMapPoses(const std::filesystem::path& poses_txt) {
  return poses::readPosesFile(poses_txt);
}

}  // namespace pmap::eval
