#include "pmap/eval/map_eval_app.h"

#include <mrpt/core/bits_math.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <system_error>

#include "pmap/common/error.h"
#include "pmap/common/text.h"
#include "pmap/config/command_line.h"
#include "pmap/eval/baseline_evaluation.h"
#include "pmap/eval/eval_outputs.h"
#include "pmap/eval/glb_mesh.h"
#include "pmap/eval/ground_truth.h"
#include "pmap/eval/label_check.h"
#include "pmap/eval/map_files.h"
#include "pmap/eval/point_labels.h"
#include "pmap/eval/pose_metrics.h"
#include "pmap/eval/surface_evaluation.h"
#include "pmap/eval/surface_files.h"
#include "pmap/eval/surface_report.h"
#include "pmap/eval/texture_quality.h"
#include "pmap/eval/voxel_evaluation.h"
#include "pmap/products/output_folder.h"
#include "pmap/products/output_layout.h"

namespace pmap::eval {
namespace fs = std::filesystem;
using nlohmann::json;
using products::OutputFolder;
using products::OutputLayout;

namespace {

std::optional<MapEvalArgs> parseArgs(int argc, const char* const* argv) {
  TCLAP::CmdLine cmd(
      "map-eval: scores a planar-mapper output directory (poses.txt, points.ply, ...) against "
      "the ground truth written by indoor-sim (PREFIX.gt.json) and/or against the occupied "
      "voxels of an OctoMap (.bt, --gt-octomap). A map without poses.txt (--cloud) is scored "
      "as it stands, in the ground truth's frame. Exit codes: 0 ok, 1 usage, 2 input data "
      "error, 4 output write error.",
      ' ', "0.1.0");
  TCLAP::ValueArg<std::string> map("m", "map", "planar-mapper output directory", true, "", "DIR",
                                   cmd);
  TCLAP::ValueArg<std::string> gt("g", "gt", "ground truth (indoor-sim PREFIX.gt.json)", false, "",
                                  "FILE", cmd);
  TCLAP::ValueArg<std::string> gt_octomap(
      "", "gt-octomap",
      "ground truth as an OctoMap's occupied voxels (.bt); the map must be in the tree's frame "
      "(with --gt, the pose alignment moves it there)",
      false, "", "FILE.bt", cmd);
  TCLAP::ValueArg<std::string> out("o", "out",
                                   "evaluation output (default ./eval.json); the OctoMap baselines "
                                   "octomap_5cm.bt and octomap_10cm.bt are written beside it",
                                   false, OutputLayout::kEvalJson, OutputLayout::kEvalJson, cmd);
  TCLAP::ValueArg<double> shift("", "texture-max-shift-px",
                                "registration search of the poster texture score, texels either "
                                "way (default 2)",
                                false, 2.0, "PX", cmd);
  TCLAP::SwitchArg quiet("q", "quiet", "no report on stdout", cmd);
  if (!config::parseCommandLine(cmd, argc, argv)) {
    return std::nullopt;
  }
  if (!(shift.getValue() >= 0.0 && shift.getValue() <= 50.0)) {
    throw ConfigError("usage: --texture-max-shift-px must be in [0, 50]");
  }
  if (gt.getValue().empty() && gt_octomap.getValue().empty()) {
    throw ConfigError(
        "usage: give --gt FILE (indoor-sim's ground truth), --gt-octomap FILE.bt, "
        "or both");
  }
  return MapEvalArgs{map.getValue(),   gt.getValue(),    out.getValue(),
                     quiet.getValue(), shift.getValue(), gt_octomap.getValue()};
}

json poseJson(const PoseErrors& e) {
  return {{"matched", e.matched},
          {"ate_m", e.ate_m},
          {"ate_first_pose_aligned_m", e.ate_first_pose_m},
          {"final_error_m", e.final_error_m},
          {"max_error_m", e.max_error_m},
          {"yaw_rms_deg", e.yaw_rms_deg},
          {"alignment",
           {{"yaw_deg", mrpt::RAD2DEG(e.alignment.yaw)},
            {"x", e.alignment.t.x()},
            {"y", e.alignment.t.y()}}}};
}

// The distances are null when no point has a labelled surface.
json labelJson(const LabelCheck& c) {
  const auto value = [&c](double v) { return c.labelled > 0 ? json(v) : json(nullptr); };
  return {{"points", c.points},
          {"labelled", c.labelled},
          {"unlabelled", c.unlabelled},
          {"on_people", c.on_people},
          {"within_3sigma", c.within_3sigma},
          {"fraction_within_3sigma", value(c.fraction_within_3sigma)},
          {"median_m", value(c.median_m)},
          {"p99_m", value(c.p99_m)},
          {"max_m", value(c.max_m)}};
}

/// The surface keys, when the map has a surfaces.csv (it needs points.ply).
void addSurfaceEvaluation(const OutputFolder& folder, const GroundTruth& gt,
                          const MapPoints* points, const Rigid2D& map_to_gt, json& doc) {
  if (!folder.has(OutputLayout::kSurfacesCsv)) {
    return;
  }
  const fs::path csv = folder.file(OutputLayout::kSurfacesCsv);
  if (points == nullptr) {
    throw InputError(csv.string() + ": needs " + OutputLayout::kPointsPly +
                     " beside it (the surface ids of the points)");
  }
  const std::vector<MapSurface> surfaces = readMapSurfaces(csv);
  checkSurfaceIds(*points, surfaces, folder.file(OutputLayout::kPointsPly));
  const SurfaceEvalOptions options;
  addSurfaceKeys(evaluateSurfaces(gt, *points, surfaces, map_to_gt, options), options, doc);
}

/// The texture keys, when the map has a textures.csv and the world posters.
void addTextureEvaluation(const MapEvalArgs& args, const OutputFolder& folder,
                          const GroundTruth& gt, const Rigid2D& map_to_gt, MapEvaluation& ev) {
  if (!folder.has(OutputLayout::kTexturesCsv) || gt.posters.empty()) {
    return;
  }
  TextureQualityOptions options;
  options.max_shift_px = args.texture_max_shift_px;
  const std::vector<MapTexture> textures = readMapTextures(folder.file(OutputLayout::kTexturesCsv));
  for (const MapTexture& t : textures) {
    ev.images.push_back(folder.file(t.file));  // only images the run wrote
  }
  for (const GtPoster& p : gt.posters) {
    ev.images.push_back(p.image);
  }
  json posters = json::array();
  double min_psnr = 0, sum = 0;
  std::size_t scored = 0;
  for (const PosterScore& s : scorePosters(gt, textures, map_to_gt, options)) {
    json p = {{"poster", s.poster_id}, {"surface", s.surface_id}};
    if (s.surface_id >= 0) {
      p.update({{"psnr_db", s.psnr_db},
                {"psnr_unshifted_db", s.psnr_unshifted_db},
                {"shift_px", {s.shift_px.x(), s.shift_px.y()}},
                {"pixels_per_m", s.pixels_per_m},
                {"cells", s.cells},
                {"covered", s.covered}});
      min_psnr = scored == 0 ? s.psnr_db : std::min(min_psnr, s.psnr_db);
      sum += s.psnr_db;
      ++scored;
    }
    posters.push_back(p);
  }
  ev.doc["texture"] = {{"posters", posters},
                       {"posters_scored", scored},
                       {"max_shift_px", options.max_shift_px},
                       {"psnr_db_min", scored > 0 ? json(min_psnr) : json(nullptr)},
                       {"psnr_db_mean", scored > 0 ? json(sum / scored) : json(nullptr)}};
}

/// The short report on stdout.
void printReport(const json& doc) {
  if (doc.contains("voxel_gt")) {
    const json& v = doc["voxel_gt"];
    std::printf(
        "voxel ground truth (%zu voxels of %.3f m): map to voxels mean %.4f m, p95 %.4f m; "
        "coverage %.4f (%.4f within the map's box)\n",
        v["occupied_voxels"].get<std::size_t>(), v["resolution_m"].get<double>(),
        v["map_to_voxels"]["mean_m"].get<double>(), v["map_to_voxels"]["p95_m"].get<double>(),
        v["coverage"].get<double>(), v["coverage_in_map_box"].get<double>());
  }
  if (!doc.contains("gt")) {
    return;  // voxel ground truth only
  }
  if (doc.contains("pose_ate_m")) {
    std::printf("pose_ate_m %.4f (first-pose aligned %.4f, %zu poses)\n",
                doc["pose_ate_m"].get<double>(),
                doc["pose"]["ate_first_pose_aligned_m"].get<double>(),
                doc["pose"]["matched"].get<std::size_t>());
  } else {
    std::printf(
        "no poses (a --cloud map): scored as it stands, points labelled by the nearest "
        "object within %.3f m\n",
        doc["labels"]["max_distance_m"].get<double>());
  }
  if (doc.contains("label_check") && !doc["label_check"]["median_m"].is_null()) {
    std::printf("points on their labelled surface within 3 sigma: %.4f (median %.4f m)\n",
                doc["label_check"]["fraction_within_3sigma"].get<double>(),
                doc["label_check"]["median_m"].get<double>());
  }
  std::fputs(surfaceReportText(doc).c_str(), stdout);
  std::fputs(baselineReportText(doc).c_str(), stdout);
  for (const json& o : doc.value("octomap", json::array())) {
    std::printf("octomap tree (octovis): %s\n", o["bt_file"].get<std::string>().c_str());
  }
  if (doc.contains("texture")) {
    for (const json& p : doc["texture"]["posters"]) {
      if (p.contains("psnr_db")) {
        std::printf("poster %d on surface %d: PSNR %.2f dB (shift %.1f, %.1f px)\n",
                    p["poster"].get<int>(), p["surface"].get<int>(), p["psnr_db"].get<double>(),
                    p["shift_px"][0].get<double>(), p["shift_px"][1].get<double>());
      } else {
        std::printf("poster %d: not textured in the map\n", p["poster"].get<int>());
      }
    }
  }
}

// `voxel_gt`: the planar map (moved by map_to_gt) against the occupied
// voxels of --gt-octomap.
void addVoxelEvaluation(const MapEvalArgs& args, const OutputFolder& folder,
                        const Rigid2D& map_to_gt, json& doc) {
  doc["gt_octomap"] = args.gt_octomap.string();
  const VoxelOptions options;
  const VoxelGroundTruth gt = readVoxelGroundTruth(args.gt_octomap, options);
  const std::optional<fs::path> geometry = planarGeometryFile(folder);
  if (!geometry) {
    throw InputError(args.map_dir.string() +
                     ": no planar map (surfaces.csv and map.glb) to score against --gt-octomap");
  }
  std::vector<Triangle3> triangles = readGlbTriangles(*geometry);
  for (Triangle3& t : triangles) {
    t = {map_to_gt.apply(t.a), map_to_gt.apply(t.b), map_to_gt.apply(t.c)};
  }
  doc["voxel_gt"] = voxelJson(voxelAccuracy(gt, triangles, options), gt, args.gt_octomap, options);
}

/// The run's and the ground truth's identity keys of eval.json.
void addSourceKeys(const MapEvalArgs& args, const GroundTruth& gt, json& doc) {
  doc["map"] = args.map_dir.string();
  doc["gt"] = args.gt.string();
  doc["world"] = gt.world;
  doc["sigma_m"] = gt.sigma_m;
}

/// Everything scored against --gt (and --gt-octomap) once the map is in the
/// ground truth's frame by map_to_gt: surfaces, textures, baselines (when
/// the map has points.ply) and voxels.
void addMapScores(const MapEvalArgs& args, const OutputFolder& folder, const GroundTruth& gt,
                  const MapPoints* points, const Rigid2D& map_to_gt,
                  const BaselineOptions& baselines, MapEvaluation& ev) {
  addSurfaceEvaluation(folder, gt, points, map_to_gt, ev.doc);
  addTextureEvaluation(args, folder, gt, map_to_gt, ev);
  if (points != nullptr) {
    ev.files = addBaselineKeys(folder, gt, *points, map_to_gt, baselines, ev.doc);
  }
  if (!args.gt_octomap.empty()) {
    addVoxelEvaluation(args, folder, map_to_gt, ev.doc);
  }
}

// A map without poses.txt (planar-mapper --cloud) has no trajectory to
// align and its points are not the ground truth's beams: it is scored as it
// stands (the cloud must be in the world's frame), its points labelled by
// the nearest ground-truth object within 3 sigma of the world's range noise
// (at least 1 cm). No pose keys, no label check (the labels are distances
// already), no OctoMap baseline (nothing to ray-cast from).
MapEvaluation evaluateWithoutPoses(const MapEvalArgs& args, const OutputFolder& folder,
                                   GroundTruth gt, MapEvaluation ev) {
  if (!folder.has(OutputLayout::kPointsPly)) {
    throw InputError(args.map_dir.string() + ": neither " + OutputLayout::kPosesTxt + " nor " +
                     OutputLayout::kPointsPly + ": nothing to score against --gt");
  }
  const MapPoints points = readMapPoints(folder.file(OutputLayout::kPointsPly));
  const auto scans =
      std::count_if(points.scan.begin(), points.scan.end(), [](int scan) { return scan != 0; });
  if (scans > 0) {  // a rawlog's map: its poses.txt is missing, not absent by design
    throw InputError(args.map_dir.string() + ": no " + OutputLayout::kPosesTxt + ", but " +
                     std::to_string(scans) + " of its points are not in scan 0 (only a --cloud " +
                     "map, one scan, comes without poses)");
  }
  NearestLabelOptions labels;
  labels.max_distance_m = std::max(0.01, 3.0 * gt.sigma_m);
  gt.hits = nearestObjectHits(gt, points, labels);
  addSourceKeys(args, gt, ev.doc);
  ev.doc["pose"] = nullptr;
  ev.doc["labels"] = {{"from", "nearest ground-truth object (the map has no poses.txt)"},
                      {"max_distance_m", labels.max_distance_m}};
  BaselineOptions baselines;
  baselines.octomap = false;
  addMapScores(args, folder, gt, &points, Rigid2D{}, baselines, ev);  // as it stands
  return ev;
}

}  // namespace

MapEvaluation runEvaluation(const MapEvalArgs& args) {
  std::error_code ec;
  if (!fs::is_directory(args.map_dir, ec)) {
    throw InputError(args.map_dir.string() +
                     ": not a directory (--map takes a planar-mapper output directory)");
  }
  MapEvaluation ev;
  const OutputFolder folder(args.map_dir);  // only the files of the run, as its manifest lists
  if (!folder.hasManifest()) {
    ev.warnings.push_back(folder.warning());
  }
  folder.verify();
  if (args.gt.empty()) {  // voxel ground truth only: no poses to compare, the map as it is
    ev.doc["map"] = args.map_dir.string();
    addVoxelEvaluation(args, folder, Rigid2D{}, ev.doc);
    return ev;
  }
  const GroundTruth gt = readGroundTruth(args.gt);
  if (gt.surfaces.empty() && gt.cylinders.empty() && gt.boxes.empty()) {
    ev.warnings.push_back(args.gt.string() +
                          " has no surfaces or objects (a voxel world's?): the map's distances "
                          "to them are null; --gt-octomap scores the map against a .bt");
  }
  if (!folder.has(OutputLayout::kPosesTxt)) {
    return evaluateWithoutPoses(args, folder, gt, std::move(ev));
  }
  const fs::path poses_txt = folder.file(OutputLayout::kPosesTxt);
  const poses::Trajectory estimated = readMapPoses(poses_txt);
  const PoseErrors pe = comparePoses(estimated, gt.poses);
  if (pe.matched == 0) {
    throw InputError(poses_txt.string() +
                     ": no pose overlaps the ground truth's time span (different run?)");
  }
  json& doc = ev.doc;
  addSourceKeys(args, gt, doc);
  doc["pose_ate_m"] = pe.ate_m;
  doc["pose"] = poseJson(pe);
  std::optional<MapPoints> points;
  if (folder.has(OutputLayout::kPointsPly)) {
    points = readMapPoints(folder.file(OutputLayout::kPointsPly));
    doc["label_check"] = labelJson(checkLabels(gt, *points, pe.alignment));
  }
  addMapScores(args, folder, gt, points ? &*points : nullptr, pe.alignment, BaselineOptions{}, ev);
  return ev;
}

json evaluateMap(const MapEvalArgs& args) {
  return runEvaluation(args).doc;
}

int mapEvalMain(int argc, const char* const* argv) {
  try {
    const auto args = parseArgs(argc, argv);
    if (!args) {
      return 0;
    }
    const std::vector<fs::path> outputs =
        outputPaths(args->out, BaselineOptions{}.octomap_resolutions_m);
    std::vector<fs::path> inputs = knownInputs(args->map_dir, args->gt);
    if (!args->gt_octomap.empty()) {
      inputs.push_back(args->gt_octomap);
    }
    checkOutputsSpareInputs(outputs, inputs);  // before any work
    checkOutputsSpareMapFiles(outputs, args->map_dir);
    MapEvaluation ev = runEvaluation(*args);
    for (const std::string& w : ev.warnings) {
      std::fprintf(stderr, "map-eval: warning: %s\n", w.c_str());
    }
    checkOutputsSpareInputs(outputs, ev.images);
    writeEvaluation(args->out, ev.files, ev.doc);
    if (!args->quiet) {
      printReport(ev.doc);
    }
    return 0;
  } catch (const Error& e) {
    std::fprintf(stderr, "map-eval: error: %s\n", e.what());
    return e.exitCode();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "map-eval: error: internal failure: %s\n", oneLineError(e.what()).c_str());
    return static_cast<int>(ExitCode::kProcessing);
  }
}

}  // namespace pmap::eval
