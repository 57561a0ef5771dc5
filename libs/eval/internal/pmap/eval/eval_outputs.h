// What map-eval writes, and never over its own inputs: the evaluation file
// (--out, usually MAP/eval.json) and, beside it, the OctoMap baselines as
// .bt files (octomap_5cm.bt, octomap_10cm.bt) for octovis.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pmap/eval/baseline_evaluation.h"

namespace pmap::eval {

/// The files map-eval reads from a map directory (names of
/// products::OutputLayout; those the manifest lists are read): manifest.json,
/// poses.txt, points.ply, scans.csv, surfaces.csv, textures.csv, map.glb,
/// map-geometry.glb, raw.glb. Texture images are listed in textures.csv.
const std::vector<std::string>& mapInputFileNames();

/// The inputs known before any work: the ground truth, map_dir's files of
/// mapInputFileNames() and every file its manifest lists (the textures).
std::vector<std::filesystem::path> knownInputs(const std::filesystem::path& map_dir,
                                               const std::filesystem::path& gt);

/// Every path map-eval may write: `out`, then one .bt file per resolution in
/// out's directory (octomapFileName).
std::vector<std::filesystem::path> outputPaths(const std::filesystem::path& out,
                                               const std::vector<double>& resolutions_m);

/// Throws OutputError (exit 4) when `outputs[0]` (--out) is a directory, or
/// when an output is an existing input file (the same file: symbolic and hard
/// links, `..` resolved). Inputs that do not exist are skipped.
void checkOutputsSpareInputs(const std::vector<std::filesystem::path>& outputs,
                             const std::vector<std::filesystem::path>& inputs);

/// Throws OutputError (exit 4) when an output lies in `map_dir` under a name
/// products::OutputLayout gives to planar-mapper (summary.json,
/// viewer.html, a reserved name, ...): it would break the map folder. Its
/// own names (eval.json, octomap_*.bt) and names the layout does not know
/// are fine.
void checkOutputsSpareMapFiles(const std::vector<std::filesystem::path>& outputs,
                               const std::filesystem::path& map_dir);

/// Writes each file beside `out` (its directory), then `doc` as `out`, each
/// atomically; each `octomap` entry's `bt_file` becomes the path written.
/// Throws OutputError.
void writeEvaluation(const std::filesystem::path& out, const std::vector<BaselineFile>& files,
                     nlohmann::json& doc);

}  // namespace pmap::eval
