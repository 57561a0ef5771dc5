// map-eval's comparison with the baselines (doc/evaluation.md, "Baselines"):
// the OctoMap built from the same scans and poses, the raw triangle map
// (raw.glb) and the planar map (map.glb / map-geometry.glb), with the same
// accuracy figures (map_accuracy.h), sizes and counts.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "pmap/eval/ground_truth.h"
#include "pmap/eval/map_accuracy.h"
#include "pmap/eval/map_files.h"
#include "pmap/eval/pose_metrics.h"
#include "pmap/products/output_folder.h"

namespace pmap::eval {

struct BaselineOptions {
  std::vector<double> octomap_resolutions_m = {0.05, 0.10};
  /// Build the OctoMap baselines (they ray-cast each scan from its origin in
  /// scans.csv; a `--cloud` map's one origin at 0 means nothing).
  bool octomap = true;
  AccuracyOptions accuracy;
  bool validate(std::string* why) const;
};

/// A baseline map for the user to open (an OctoMap tree for octovis), which
/// map-eval writes beside its evaluation file.
struct BaselineFile {
  std::string name;   ///< octomap_5cm.bt, octomap_10cm.bt
  std::string bytes;  ///< the file (OcTree::writeBinary's content)
};

/// Adds, where the map folder has the files (written by its run, as its
/// manifest lists): `octomap` (scans.csv and points.ply), `raw_map`
/// (raw.glb), `planar_map` (surfaces.csv and map.glb), and
/// `baseline_accuracy` (the sampling used). `points` are the folder's
/// points.ply, `map_to_gt` the pose alignment. Reads (and so checks) every
/// file it needs before it builds the first OctoMap: a bad file is an
/// InputError at once. Returns the OctoMap trees as .bt files (none without
/// scans.csv); each `octomap` entry names its file in `bt_file`. Writes
/// nothing.
std::vector<BaselineFile> addBaselineKeys(const products::OutputFolder& map_folder,
                                          const GroundTruth& gt, const MapPoints& points,
                                          const Rigid2D& map_to_gt, const BaselineOptions& options,
                                          nlohmann::json& doc);

/// The file holding the planar map's geometry alone: map-geometry.glb when
/// the map is textured, else map.glb; none without a planar map.
std::optional<std::filesystem::path> planarGeometryFile(const products::OutputFolder& folder);

/// A few lines for map-eval's report: each map's mean / p95 error and size.
std::string baselineReportText(const nlohmann::json& doc);

}  // namespace pmap::eval
