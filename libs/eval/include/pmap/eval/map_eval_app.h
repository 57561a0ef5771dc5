// map-eval: scores a planar-mapper output directory against the simulator's
// ground truth (doc/evaluation.md). A class so tests run it in-process.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>

namespace pmap::eval {

struct MapEvalArgs {
  std::filesystem::path map_dir;
  std::filesystem::path gt;
  std::filesystem::path out = "eval.json";
  bool quiet = false;
  double texture_max_shift_px = 2.0;  ///< poster texture registration search (texels)
};

/// Computes the evaluation document (throws InputError for unreadable inputs).
nlohmann::json evaluateMap(const MapEvalArgs& args);

/// main() of map-eval: parses argv, evaluates, writes --out, prints a short
/// report; returns the documented exit code (errors: one line on stderr).
int mapEvalMain(int argc, const char* const* argv);

}  // namespace pmap::eval
