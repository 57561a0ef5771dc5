// The one list of the files in planar-mapper's output folder (doc/outputs.md):
// what a run writes, the names reserved for outputs still to come, and what
// map-eval writes beside a map. The writers, the overwrite guards of
// planar-mapper and map-eval, the run's manifest, map-eval's readers, the
// report and the viewer take the names from here; no other code spells them.
//
// A name is a path relative to the folder, '/'-separated. Pattern entries
// stand for a family of files: "<n>" is an integer, "<x>" a decimal number
// (textures/surface_<n>_<n>.png, octomap_<x>cm.bt).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pmap::products {

struct LayoutEntry {
  enum class Kind { kFile, kDirectory, kPattern };
  enum class Owner {
    kRun,         ///< written by planar-mapper (listed in its manifest)
    kReserved,    ///< reserved for an output not written yet
    kEvaluation,  ///< written by map-eval beside the map (not in the manifest)
  };
  std::string name;
  Kind kind;
  Owner owner;
  std::string what;  ///< one line, as in doc/outputs.md
};

class OutputLayout {
 public:
  // The folder's root.
  static constexpr const char* kManifest = "manifest.json";
  static constexpr const char* kEffectiveIni = "effective.ini";
  static constexpr const char* kSummary = "summary.json";
  static constexpr const char* kPosesTxt = "poses.txt";
  static constexpr const char* kPosesTum = "poses.tum";
  static constexpr const char* kScansCsv = "scans.csv";
  static constexpr const char* kPointsPly = "points.ply";
  static constexpr const char* kRawWrl = "raw.wrl";
  static constexpr const char* kRawGlb = "raw.glb";
  static constexpr const char* kOnlineCsv = "online.csv";
  static constexpr const char* kSurfacesCsv = "surfaces.csv";
  static constexpr const char* kMapWrl = "map.wrl";
  static constexpr const char* kMapGlb = "map.glb";
  static constexpr const char* kMapGeometryGlb = "map-geometry.glb";
  static constexpr const char* kTexturesCsv = "textures.csv";
  static constexpr const char* kFramesCsv = "frames.csv";
  static constexpr const char* kMapScene = "map.3Dscene";
  static constexpr const char* kViewerHtml = "viewer.html";
  // Folders, and the files in them (names relative to their folder).
  static constexpr const char* kTexturesDir = "textures";
  static constexpr const char* kReportDir = "report";
  static constexpr const char* kReportHtml = "report.html";
  static constexpr const char* kReportPerspective = "map_perspective.png";
  static constexpr const char* kReportTop = "map_top.png";
  static constexpr const char* kReportIterations = "em_iterations.png";
  static constexpr const char* kReportPerScan = "em_per_scan.png";
  static constexpr const char* kSnapshotsDir = "snapshots";
  static constexpr const char* kPosesGraph = "poses.graph";  ///< with loop closure
  // Reserved for outputs of issue 15 not written yet.
  static constexpr const char* kGridPng = "grid.png";
  static constexpr const char* kGridMap = "grid.gridmap.gz";
  static constexpr const char* kSimpleMap = "map.simplemap";
  // map-eval's outputs when its --out is in the map folder.
  static constexpr const char* kEvalJson = "eval.json";

  /// "textures/surface_<id>.png" and "textures/surface_<id>_<tile>.png".
  static std::string textureFile(std::int32_t surface_id);
  static std::string textureFile(std::int32_t surface_id, std::int32_t tile);
  /// "snapshots/map_NNNNNN.wrl" (6 digits at least): the map after `scans`
  /// structure scans.
  static std::string snapshotFile(std::size_t scans);
  /// "octomap_5cm.bt", "octomap_2.5cm.bt": an OctoMap baseline (0.1 mm steps).
  static std::string octomapFile(double resolution_m);

  /// Every entry, in the order of doc/outputs.md.
  static const std::vector<LayoutEntry>& entries();

  /// True when the layout names `relative`: an entry, a file of a pattern,
  /// or the temporary / backup of a named file or folder left by an atomic
  /// write ("<name>.tmp-<pid>", "<name>.old-<pid>").
  static bool names(const std::string& relative);

  /// The entry that names `relative` (temporaries: the file's), or nullptr.
  static const LayoutEntry* find(const std::string& relative);

  /// True for files a reader accepts without the manifest listing them:
  /// manifest.json itself and map-eval's outputs (eval.json, octomap_*.bt).
  static bool manifestExempt(const std::string& relative);
};

}  // namespace pmap::products
