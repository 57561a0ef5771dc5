#include "pmap/eval/eval_outputs.h"

#include <system_error>

#include "pmap/common/atomic_file.h"
#include "pmap/common/error.h"
#include "pmap/eval/octomap_baseline.h"
#include "pmap/products/json_file.h"

namespace pmap::eval {
namespace fs = std::filesystem;

namespace {

/// True when writing `output` would replace the existing file `input`.
bool sameFile(const fs::path& output, const fs::path& input) {
  std::error_code ec;
  const bool same = fs::equivalent(output, input, ec);
  return same && !ec;  // an error: one of them does not exist
}

}  // namespace

const std::vector<std::string>& mapInputFileNames() {
  static const std::vector<std::string> names = {"poses.txt",        "points.ply",   "scans.csv",
                                                 "surfaces.csv",     "textures.csv", "map.glb",
                                                 "map-geometry.glb", "raw.glb"};
  return names;
}

std::vector<fs::path> knownInputs(const fs::path& map_dir, const fs::path& gt) {
  std::vector<fs::path> inputs = {gt};
  for (const std::string& name : mapInputFileNames()) {
    inputs.push_back(map_dir / name);
  }
  return inputs;
}

std::vector<fs::path> outputPaths(const fs::path& out, const std::vector<double>& resolutions_m) {
  std::vector<fs::path> paths = {out};
  for (const double r : resolutions_m) {
    paths.push_back(out.parent_path() / octomapFileName(r));
  }
  return paths;
}

void checkOutputsSpareInputs(const std::vector<fs::path>& outputs,
                             const std::vector<fs::path>& inputs) {
  std::error_code ec;
  if (!outputs.empty() && fs::is_directory(outputs[0], ec)) {
    throw OutputError(outputs[0].string() +
                      ": --out is a directory; it names the evaluation file (e.g. MAP/eval.json)");
  }
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    for (const fs::path& input : inputs) {
      if (!sameFile(outputs[k], input)) {
        continue;
      }
      const std::string what =
          k == 0 ? "--out " + outputs[k].string() : outputs[k].string() + " (written beside --out)";
      throw OutputError(what + " would overwrite the input file " + input.string() +
                        "; choose another --out");
    }
  }
}

void writeEvaluation(const fs::path& out, const std::vector<BaselineFile>& files,
                     nlohmann::json& doc) {
  for (const BaselineFile& f : files) {
    const fs::path path = out.parent_path() / f.name;
    writeFileAtomically(
        path, [&](std::ostream& s) { s << f.bytes; }, true);
    if (!doc.contains("octomap")) {
      continue;
    }
    for (nlohmann::json& e : doc["octomap"]) {
      if (e.value("bt_file", std::string()) == f.name) {
        e["bt_file"] = path.string();
      }
    }
  }
  products::writeJsonFile(out, doc);
}

}  // namespace pmap::eval
