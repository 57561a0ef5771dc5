#include "pmap/eval/eval_outputs.h"

#include <system_error>

#include "pmap/common/atomic_file.h"
#include "pmap/common/error.h"
#include "pmap/eval/octomap_baseline.h"
#include "pmap/products/json_file.h"
#include "pmap/products/output_layout.h"
#include "pmap/products/output_manifest.h"

namespace pmap::eval {
namespace fs = std::filesystem;
using products::LayoutEntry;
using products::OutputLayout;

namespace {

/// True when writing `output` would replace the existing file `input`.
bool sameFile(const fs::path& output, const fs::path& input) {
  std::error_code ec;
  const bool same = fs::equivalent(output, input, ec);
  return same && !ec;  // an error: one of them does not exist
}

}  // namespace

const std::vector<std::string>& mapInputFileNames() {
  using L = OutputLayout;
  static const std::vector<std::string> names = {L::kManifest, L::kPosesTxt,       L::kPointsPly,
                                                 L::kScansCsv, L::kSurfacesCsv,    L::kTexturesCsv,
                                                 L::kMapGlb,   L::kMapGeometryGlb, L::kRawGlb};
  return names;
}

std::vector<fs::path> knownInputs(const fs::path& map_dir, const fs::path& gt) {
  std::vector<fs::path> inputs = {gt};
  for (const std::string& name : mapInputFileNames()) {
    inputs.push_back(map_dir / name);
  }
  try {  // the texture images; a bad manifest is reported when it is read
    for (const products::ManifestFile& f :
         products::readManifest(map_dir / OutputLayout::kManifest).files) {
      inputs.push_back(map_dir / f.path);
    }
  } catch (const Error&) {
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

void checkOutputsSpareMapFiles(const std::vector<fs::path>& outputs, const fs::path& map_dir) {
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    std::error_code ec;
    const fs::path dir = outputs[k].parent_path().empty() ? "." : outputs[k].parent_path();
    if (!fs::equivalent(dir, map_dir, ec) || ec) {
      continue;
    }
    const std::string name = outputs[k].filename().string();
    const LayoutEntry* e = OutputLayout::find(name);
    if (e == nullptr || e->owner == LayoutEntry::Owner::kEvaluation) {
      continue;
    }
    const std::string what =
        k == 0 ? "--out " + outputs[k].string() : outputs[k].string() + " (written beside --out)";
    throw OutputError(what + " would replace " + name +
                      ", a planar-mapper output of the map folder; choose another --out");
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
