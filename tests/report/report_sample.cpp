// report-sample OUT [DEST]: builds a MapModel from a planar-mapper output
// directory (surfaces.csv coloured by orientation as in map.wrl, poses.txt as
// the path) and writes DEST/report/ and DEST/map.3Dscene (DEST defaults to
// OUT). Made the sample pictures in doc/images/ (doc/report.md).
#include <algorithm>
#include <cmath>
#include <exception>
#include <fstream>
#include <iostream>

#include "pmap/common/atomic_file.h"
#include "pmap/common/error.h"
#include "pmap/common/text.h"
#include "pmap/poses/poses_file.h"
#include "pmap/products/output_folder.h"
#include "pmap/products/output_layout.h"
#include "pmap/report/report.h"
#include "pmap/scene/map_scene.h"
#include "pmap/scene/scene_file.h"

namespace {
namespace fs = std::filesystem;
using namespace pmap;

/// surfaces.csv (doc/outputs.md): id, nx ny nz, offset, x0 y0 z0 .. x3 y3 z3,
/// support.
std::vector<products::TexturedQuad> readSurfaces(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  if (!in || !std::getline(in, line) || line.rfind("id,nx,ny,nz,offset,x0", 0) != 0) {
    throw InputError(csv.string() + ": missing or not a surfaces.csv");
  }
  std::vector<products::TexturedQuad> quads;
  for (int number = 2; std::getline(in, line); ++number) {
    const std::vector<std::string> f = splitFields(line, ",");
    std::vector<double> v;
    for (const auto& field : f) {
      v.push_back(parseDouble(field).value_or(NAN));
    }
    if (v.size() != 18 ||
        !std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); })) {
      throw InputError(csv.string() + ": line " + std::to_string(number) + ": malformed");
    }
    products::TexturedQuad q;
    q.surface_id = static_cast<int>(v[0]);
    q.normal = Eigen::Vector3d(v[1], v[2], v[3]).normalized();
    for (int c = 0; c < 4; ++c) {
      q.corners[c] = Eigen::Vector3d(v[5 + 3 * c], v[6 + 3 * c], v[7 + 3 * c]);
    }
    const double vertical = std::abs(q.normal.z());  // colours of map.wrl
    q.color = vertical < 0.2   ? Eigen::Vector3d(0.85, 0.83, 0.78)
              : vertical > 0.9 ? Eigen::Vector3d(0.70, 0.78, 0.88)
                               : Eigen::Vector3d(0.80, 0.70, 0.85);
    quads.push_back(q);
  }
  return quads;
}

/// The run's files, as its manifest lists them (doc/outputs.md).
products::MapModel modelOf(const products::OutputFolder& out) {
  using products::OutputLayout;
  products::MapModel model;
  model.quads = readSurfaces(out.file(OutputLayout::kSurfacesCsv));
  const poses::Trajectory trajectory = poses::readPosesFile(out.file(OutputLayout::kPosesTxt));
  for (const auto& p : trajectory.poses()) {
    model.path.emplace_back(p.pose.x, p.pose.y, p.pose.z);
  }
  return model;
}

nlohmann::json readJson(const fs::path& file) {
  std::ifstream in(file);
  if (!in) {
    throw InputError(file.string() + ": cannot open");
  }
  return nlohmann::json::parse(in);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::cerr << "usage: report-sample OUT [DEST]\n";
    return 1;
  }
  try {
    const products::OutputFolder out(argv[1]);  // only files its manifest lists
    if (!out.warning().empty()) {
      std::cerr << "warning: " << out.warning() << "\n";
    }
    const fs::path dest = argc == 3 ? fs::path(argv[2]) : out.dir();
    const products::MapModel model = modelOf(out);
    std::vector<report::OnlineScanRow> rows;
    if (out.has(products::OutputLayout::kOnlineCsv)) {
      rows = report::readOnlineCsv(out.file(products::OutputLayout::kOnlineCsv));
    }
    ensureWritableDirectory(dest);
    scene::writeMapScene(dest / products::OutputLayout::kMapScene,
                         *scene::buildMapScene(model, {}));
    const report::ReportResult r = report::writeReport(
        dest, {model, readJson(out.file(products::OutputLayout::kSummary)), rows});
    for (const auto& w : r.warnings) {
      std::cerr << "warning: " << w << "\n";
    }
    std::cout << r.dir.string() << ": " << r.files.size() << " files\n";
    return 0;
  } catch (const Error& e) {
    std::cerr << "report-sample: " << e.what() << "\n";
    return e.exitCode();
  } catch (const std::exception& e) {
    std::cerr << "report-sample: " << e.what() << "\n";
    return 3;
  }
}
