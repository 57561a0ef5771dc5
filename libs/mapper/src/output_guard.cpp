#include "pmap/mapper/output_guard.h"

#include <algorithm>
#include <system_error>

#include "pmap/common/error.h"

namespace pmap::mapper {
namespace fs = std::filesystem;

namespace {

fs::path resolved(const fs::path& p) {
  std::error_code ec;
  fs::path r = fs::weakly_canonical(fs::absolute(p, ec), ec);
  return ec ? fs::absolute(p).lexically_normal() : r;
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// True when planar-mapper may write `input` as one of its outputs in `out`.
bool isAnOutputPath(const fs::path& out, const fs::path& input) {
  const fs::path rel = input.lexically_relative(out);
  if (rel.empty() || *rel.begin() == "..") {
    return false;  // not inside the output directory
  }
  const std::string first = rel.begin()->string();
  return std::distance(rel.begin(), rel.end()) == 1 ? contains(outputFileNames(), first)
                                                    : contains(outputSubdirectories(), first);
}

}  // namespace

const std::vector<std::string>& outputFileNames() {
  static const std::vector<std::string> names = {
      "effective.ini", "poses.txt",    "scans.csv",   "points.ply",   "raw.wrl",
      "online.csv",    "surfaces.csv", "map.wrl",     "textures.csv", "frames.csv",
      "map.glb",       "viewer.html",  "map.3Dscene", "summary.json"};
  return names;
}

const std::vector<std::string>& outputSubdirectories() {
  static const std::vector<std::string> dirs = {"report", "snapshots", "textures"};
  return dirs;
}

void checkOutputsSpareInputs(const MapperArgs& args) {
  const fs::path out = resolved(args.out);
  for (const fs::path& input : {args.rawlog, args.cloud, args.poses, args.config}) {
    std::error_code ec;
    if (input.empty() || !fs::exists(input, ec)) {
      continue;  // a missing input is reported by its reader
    }
    const fs::path in = resolved(input);
    if (in == out) {
      throw OutputError(args.out.string() + ": the output directory is the input file " +
                        input.string() + "; choose another --out");
    }
    if (isAnOutputPath(out, in)) {
      throw OutputError(args.out.string() +
                        ": writing the outputs would overwrite the input file " + input.string() +
                        "; choose another --out");
    }
  }
}

}  // namespace pmap::mapper
