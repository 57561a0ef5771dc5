#include "pmap/eval/surface_files.h"

#include <cmath>
#include <fstream>
#include <limits>
#include <string>
#include <unordered_set>

#include "pmap/common/error.h"
#include "pmap/common/text.h"
#include "pmap/eval/csv_row.h"

namespace pmap::eval {

const char* const kSurfacesCsvHeader =
    "id,nx,ny,nz,offset,x0,y0,z0,x1,y1,z1,x2,y2,z2,x3,y3,z3,support";

namespace {

constexpr std::size_t kColumns = 18;
constexpr double kUnitNormalTolerance = 1e-3;

MapSurface parseRow(const std::string& line, const std::string& where) {
  const std::vector<std::string> fields = splitCsv(line);
  const RowParser row(fields, where);
  if (fields.size() != kColumns) {
    row.fail("expected " + std::to_string(kColumns) + " comma-separated columns, got " +
             std::to_string(fields.size()));
  }
  MapSurface s;
  const std::int64_t id = row.count(0, "id");
  if (id > std::numeric_limits<int>::max()) {
    row.fail("id " + std::to_string(id) + " is too large");
  }
  s.id = static_cast<int>(id);
  s.normal = {row.number(1), row.number(2), row.number(3)};
  s.offset_m = row.number(4);
  for (std::size_t k = 0; k < 4; ++k) {
    s.corners[k] = {row.number(5 + 3 * k), row.number(6 + 3 * k), row.number(7 + 3 * k)};
  }
  s.support = row.count(17, "support");
  const double norm = s.normal.norm();
  if (std::abs(norm - 1.0) > kUnitNormalTolerance) {
    row.fail("normal length " + std::to_string(norm) + " is not 1 (tolerance 1e-3)");
  }
  s.normal /= norm;  // the same plane, exactly unit
  s.offset_m /= norm;
  return s;
}

}  // namespace

std::vector<MapSurface> readMapSurfaces(const std::filesystem::path& csv) {
  requireRegularFile(csv);
  std::ifstream in(csv);
  if (!in) {
    throw InputError(csv.string() + ": cannot open surfaces file");
  }
  std::string line;
  if (!std::getline(in, line) || trim(line) != kSurfacesCsvHeader) {
    throw InputError(csv.string() + ":1: header is not '" + std::string(kSurfacesCsvHeader) + "'");
  }
  std::vector<MapSurface> surfaces;
  std::unordered_set<int> ids;
  int lineno = 1;
  while (std::getline(in, line)) {
    ++lineno;
    const std::string where = csv.string() + ":" + std::to_string(lineno) + ": ";
    const std::string text = trim(line);
    if (text.empty()) {
      throw InputError(where + "empty line");
    }
    MapSurface s = parseRow(text, where);
    if (!ids.insert(s.id).second) {
      throw InputError(where + "duplicate surface id " + std::to_string(s.id));
    }
    surfaces.push_back(s);
  }
  return surfaces;
}

void checkSurfaceIds(const MapPoints& points, const std::vector<MapSurface>& surfaces,
                     const std::filesystem::path& ply) {
  std::unordered_set<int> ids;
  for (const auto& s : surfaces) {
    ids.insert(s.id);
  }
  for (std::size_t i = 0; i < points.surface.size(); ++i) {
    const int id = points.surface[i];
    if (id != -1 && ids.count(id) == 0) {
      throw InputError(ply.string() + ": vertex " + std::to_string(i) + " has surface id " +
                       std::to_string(id) + ", which is neither -1 nor a row of surfaces.csv");
    }
  }
}

MapSurface movedSurface(const MapSurface& s, const Rigid2D& motion) {
  MapSurface m = s;
  m.normal = motion.rotate(s.normal);
  for (std::size_t k = 0; k < 4; ++k) {
    m.corners[k] = motion.apply(s.corners[k]);
  }
  // n' . (R x + t) = n . x + n' . t
  m.offset_m = s.offset_m + m.normal.head<2>().dot(motion.t);
  return m;
}

}  // namespace pmap::eval
