// map-eval: scores a planar-mapper output directory against the simulator's
// ground truth (doc/evaluation.md). A class so tests run it in-process.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pmap/eval/baseline_evaluation.h"

namespace pmap::eval {

struct MapEvalArgs {
  std::filesystem::path map_dir;
  std::filesystem::path gt;
  std::filesystem::path out = "eval.json";
  bool quiet = false;
  double texture_max_shift_px = 2.0;  ///< poster texture registration search (texels)
  /// --gt-octomap: occupied voxels as ground truth (voxel_evaluation.h);
  /// `gt` may then be empty.
  std::filesystem::path gt_octomap{};
};

/// A whole evaluation, before anything is written.
struct MapEvaluation {
  nlohmann::json doc;                         ///< eval.json
  std::vector<BaselineFile> files;            ///< to write beside it (octomap_5cm.bt, ...)
  std::vector<std::filesystem::path> images;  ///< image files read (textures, posters)
  std::vector<std::string> warnings;          ///< one line each (a map folder without manifest)
};

/// Reads the inputs and computes everything; writes nothing. Reads only the
/// map files its manifest.json lists, after checking every listed file's
/// size and SHA-256 (products::OutputFolder); a folder without manifest is
/// read as before, with a warning. Throws InputError for unreadable or
/// invalid inputs and for map files that do not match the manifest.
MapEvaluation runEvaluation(const MapEvalArgs& args);

/// The evaluation document alone (runEvaluation(args).doc).
nlohmann::json evaluateMap(const MapEvalArgs& args);

/// main() of map-eval: parses argv, refuses outputs that would replace an
/// input (exit 4, before any work), evaluates, writes the .bt files and
/// --out, prints a short report; returns the documented exit code (errors:
/// one line on stderr).
int mapEvalMain(int argc, const char* const* argv);

}  // namespace pmap::eval
