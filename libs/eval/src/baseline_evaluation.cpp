#include "pmap/eval/baseline_evaluation.h"

#include <cstdio>
#include <optional>
#include <stdexcept>

#include "pmap/eval/glb_mesh.h"
#include "pmap/eval/octomap_baseline.h"
#include "pmap/products/output_layout.h"

namespace pmap::eval {
namespace fs = std::filesystem;
using nlohmann::json;
using products::OutputFolder;
using products::OutputLayout;

namespace {

// Null distances when the ground truth has no geometry to sample (a voxel
// world's gt.json: its geometry is the .bt, scored by --gt-octomap): a
// zero would read as a perfect map, the cap as a bad one.
void addAccuracy(const MapAccuracy& a, json& out) {
  const bool scored = a.gt_to_map.samples > 0;
  const auto value = [scored](double v) { return scored ? json(v) : json(nullptr); };
  out["mean_error_m"] = value(a.gt_to_map.mean_m);
  out["p95_error_m"] = value(a.gt_to_map.p95_m);
  out["map_to_gt_mean_error_m"] = value(a.map_to_gt.mean_m);
  out["map_to_gt_p95_error_m"] = value(a.map_to_gt.p95_m);
  out["map_samples"] = a.map_to_gt.samples;
}

/// A mesh file of the map, read (and so validated) before any baseline is built.
struct MeshFile {
  fs::path path;
  std::vector<Triangle3> triangles;
  std::int64_t bytes = 0;
};

MeshFile readMesh(const fs::path& glb) {
  MeshFile m{glb, readGlbTriangles(glb), 0};
  m.bytes = static_cast<std::int64_t>(fs::file_size(glb));
  return m;
}

/// Every map file the baselines need, read before the first OctoMap is
/// built: a bad file fails at once, with nothing built or written.
struct BaselineInputs {
  std::optional<ScanOrigins> origins;  ///< scans.csv, when the run wrote it
  fs::path points_ply;
  std::optional<MeshFile> raw;  ///< raw.glb
  bool planar = false;          ///< surfaces.csv and map.glb
  bool textured = false;        ///< textures.csv: the geometry is map-geometry.glb
  std::optional<MeshFile> planar_geometry;
  std::int64_t map_glb_bytes = 0;
};

BaselineInputs readBaselineInputs(const OutputFolder& folder) {
  using L = OutputLayout;
  BaselineInputs in;
  in.points_ply = folder.file(L::kPointsPly);
  if (folder.has(L::kScansCsv)) {
    in.origins = readScanOrigins(folder.file(L::kScansCsv));
  }
  if (folder.has(L::kRawGlb)) {
    in.raw = readMesh(folder.file(L::kRawGlb));
  }
  in.planar = folder.has(L::kSurfacesCsv) && folder.has(L::kMapGlb);
  if (in.planar) {
    in.textured = folder.has(L::kTexturesCsv);
    if (const auto geometry = planarGeometryFile(folder)) {
      in.planar_geometry = readMesh(*geometry);
    }
    in.map_glb_bytes = static_cast<std::int64_t>(fs::file_size(folder.file(L::kMapGlb)));
  }
  return in;
}

json octomapJson(const BaselineInputs& in, const GroundTruth& gt, const MapPoints& points,
                 const std::vector<Eigen::Vector3d>& samples, const Rigid2D& map_to_gt,
                 const BaselineOptions& options, std::vector<BaselineFile>& files) {
  json list = json::array();
  for (const double res : options.octomap_resolutions_m) {
    OctomapOptions o;
    o.resolution_m = res;
    OctomapResult r = buildOctomap(*in.origins, points, o, in.points_ply);
    files.push_back({octomapFileName(res), std::move(r.bt_file)});
    json e = {{"resolution_m", r.resolution_m},
              {"scans", r.scans},
              {"points", r.points},
              {"insert_s", r.insert_s},
              {"memory_bytes", r.memory_bytes},
              {"file_bytes", r.file_bytes},
              {"nodes", r.nodes},
              {"leaves", r.leaves},
              {"occupied_leaves", r.occupied_leaves},
              {"occupied_voxels", r.occupied_centres.size()},
              {"bt_file", files.back().name}};
    addAccuracy(pointAccuracy(r.occupied_centres, gt, samples, map_to_gt, options.accuracy), e);
    list.push_back(e);
  }
  return list;
}

json meshJson(const MeshFile& mesh, const GroundTruth& gt,
              const std::vector<Eigen::Vector3d>& samples, const Rigid2D& map_to_gt,
              const BaselineOptions& options) {
  json e = {{"file", mesh.path.filename().string()},
            {"triangles", mesh.triangles.size()},
            {"file_bytes", mesh.bytes}};
  if (mesh.triangles.empty()) {  // a --cloud map's raw.glb: every distance would be the cap
    e["reason"] = "no triangles";
    return e;
  }
  addAccuracy(meshAccuracy(mesh.triangles, gt, samples, map_to_gt, options.accuracy), e);
  return e;
}

/// The planar map's geometry alone: map-geometry.glb when the map is
/// textured, else map.glb (an untextured map.glb is geometry only).
json planarJson(const BaselineInputs& in, const GroundTruth& gt,
                const std::vector<Eigen::Vector3d>& samples, const Rigid2D& map_to_gt,
                const BaselineOptions& options) {
  if (!in.planar_geometry) {
    return {{"file", nullptr},
            {"reason", std::string("textured map without ") + OutputLayout::kMapGeometryGlb}};
  }
  json e = meshJson(*in.planar_geometry, gt, samples, map_to_gt, options);
  e["texture_bytes"] = in.textured ? in.map_glb_bytes - in.planar_geometry->bytes : 0;
  e["map_glb_bytes"] = in.map_glb_bytes;
  return e;
}

}  // namespace

bool BaselineOptions::validate(std::string* why) const {
  for (const double r : octomap_resolutions_m) {
    OctomapOptions o;
    o.resolution_m = r;
    if (!o.validate(why))
      return false;
  }
  return accuracy.validate(why);
}

std::optional<fs::path> planarGeometryFile(const OutputFolder& folder) {
  using L = OutputLayout;
  if (!folder.has(L::kSurfacesCsv) || !folder.has(L::kMapGlb)) {
    return std::nullopt;
  }
  const char* geometry = folder.has(L::kTexturesCsv) ? L::kMapGeometryGlb : L::kMapGlb;
  if (!folder.has(geometry)) {
    return std::nullopt;
  }
  return folder.file(geometry);
}

std::vector<BaselineFile> addBaselineKeys(const OutputFolder& folder, const GroundTruth& gt,
                                          const MapPoints& points, const Rigid2D& map_to_gt,
                                          const BaselineOptions& options, json& doc) {
  std::string why;
  if (!options.validate(&why)) {
    throw std::invalid_argument("BaselineOptions: " + why);
  }
  const BaselineInputs in = readBaselineInputs(folder);  // every file checked before any work
  const std::vector<Eigen::Vector3d> samples =
      groundTruthSamples(gt, points, map_to_gt, options.accuracy);
  doc["baseline_accuracy"] = {{"gt_samples", samples.size()},
                              {"sample_spacing_m", options.accuracy.sample_spacing_m},
                              {"mesh_sample_m", options.accuracy.mesh_sample_m},
                              {"max_distance_m", options.accuracy.index.max_distance_m}};
  std::vector<BaselineFile> files;
  if (in.origins && options.octomap) {
    doc["octomap"] = octomapJson(in, gt, points, samples, map_to_gt, options, files);
  }
  if (in.raw) {
    doc["raw_map"] = meshJson(*in.raw, gt, samples, map_to_gt, options);
  }
  if (in.planar) {
    doc["planar_map"] = planarJson(in, gt, samples, map_to_gt, options);
  }
  return files;
}

std::string baselineReportText(const json& doc) {
  std::string text;
  char line[200];
  const auto add = [&](const std::string& name, const json& e) {
    if (!e.contains("mean_error_m") || e["mean_error_m"].is_null())
      return;
    std::snprintf(line, sizeof line, "%s: error mean %.4f m, p95 %.4f m; %lld bytes\n",
                  name.c_str(), e["mean_error_m"].get<double>(), e["p95_error_m"].get<double>(),
                  e["file_bytes"].get<long long>());
    text += line;
  };
  if (doc.contains("planar_map"))
    add("planar map", doc["planar_map"]);
  if (doc.contains("raw_map"))
    add("raw map", doc["raw_map"]);
  for (const json& o : doc.value("octomap", json::array())) {
    add("octomap " + std::to_string(static_cast<int>(o["resolution_m"].get<double>() * 100 + 0.5)) +
            " cm",
        o);
  }
  return text;
}

}  // namespace pmap::eval
