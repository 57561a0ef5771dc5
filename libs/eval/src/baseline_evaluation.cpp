#include "pmap/eval/baseline_evaluation.h"

#include <cstdio>
#include <stdexcept>

#include "pmap/eval/glb_mesh.h"
#include "pmap/eval/octomap_baseline.h"

namespace pmap::eval {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

void addAccuracy(const MapAccuracy& a, json& out) {
  out["mean_error_m"] = a.gt_to_map.mean_m;
  out["p95_error_m"] = a.gt_to_map.p95_m;
  out["map_to_gt_mean_error_m"] = a.map_to_gt.mean_m;
  out["map_to_gt_p95_error_m"] = a.map_to_gt.p95_m;
  out["map_samples"] = a.map_to_gt.samples;
}

json octomapJson(const fs::path& dir, const GroundTruth& gt, const MapPoints& points,
                 const std::vector<Eigen::Vector3d>& samples, const Rigid2D& map_to_gt,
                 const BaselineOptions& options, std::vector<BaselineFile>& files) {
  const ScanOrigins origins = readScanOrigins(dir / "scans.csv");
  json list = json::array();
  for (const double res : options.octomap_resolutions_m) {
    OctomapOptions o;
    o.resolution_m = res;
    OctomapResult r = buildOctomap(origins, points, o, dir / "points.ply");
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

json meshJson(const fs::path& glb, const GroundTruth& gt,
              const std::vector<Eigen::Vector3d>& samples, const Rigid2D& map_to_gt,
              const BaselineOptions& options) {
  const std::vector<Triangle3> triangles = readGlbTriangles(glb);
  json e = {{"file", glb.filename().string()},
            {"triangles", triangles.size()},
            {"file_bytes", fs::file_size(glb)}};
  addAccuracy(meshAccuracy(triangles, gt, samples, map_to_gt, options.accuracy), e);
  return e;
}

/// The planar map's geometry alone: map-geometry.glb when the map is
/// textured, else map.glb (an untextured map.glb is geometry only).
json planarJson(const fs::path& dir, const GroundTruth& gt,
                const std::vector<Eigen::Vector3d>& samples, const Rigid2D& map_to_gt,
                const BaselineOptions& options) {
  const bool textured = fs::exists(dir / "textures.csv");
  const fs::path geometry = textured ? dir / "map-geometry.glb" : dir / "map.glb";
  if (!fs::exists(geometry)) {
    return {{"file", nullptr}, {"reason", "textured map without map-geometry.glb"}};
  }
  json e = meshJson(geometry, gt, samples, map_to_gt, options);
  const auto map_bytes = static_cast<std::int64_t>(fs::file_size(dir / "map.glb"));
  e["texture_bytes"] = textured ? map_bytes - e["file_bytes"].get<std::int64_t>() : 0;
  e["map_glb_bytes"] = map_bytes;
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

std::vector<BaselineFile> addBaselineKeys(const fs::path& dir, const GroundTruth& gt,
                                          const MapPoints& points, const Rigid2D& map_to_gt,
                                          const BaselineOptions& options, json& doc) {
  std::string why;
  if (!options.validate(&why)) {
    throw std::invalid_argument("BaselineOptions: " + why);
  }
  const std::vector<Eigen::Vector3d> samples =
      groundTruthSamples(gt, points, map_to_gt, options.accuracy);
  doc["baseline_accuracy"] = {{"gt_samples", samples.size()},
                              {"sample_spacing_m", options.accuracy.sample_spacing_m},
                              {"mesh_sample_m", options.accuracy.mesh_sample_m},
                              {"max_distance_m", options.accuracy.index.max_distance_m}};
  std::vector<BaselineFile> files;
  if (fs::exists(dir / "scans.csv")) {
    doc["octomap"] = octomapJson(dir, gt, points, samples, map_to_gt, options, files);
  }
  if (fs::exists(dir / "raw.glb")) {
    doc["raw_map"] = meshJson(dir / "raw.glb", gt, samples, map_to_gt, options);
  }
  if (fs::exists(dir / "surfaces.csv") && fs::exists(dir / "map.glb")) {
    doc["planar_map"] = planarJson(dir, gt, samples, map_to_gt, options);
  }
  return files;
}

std::string baselineReportText(const json& doc) {
  std::string text;
  char line[200];
  const auto add = [&](const std::string& name, const json& e) {
    if (!e.contains("mean_error_m"))
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
