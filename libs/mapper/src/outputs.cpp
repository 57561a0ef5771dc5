#include "pmap/mapper/outputs.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <numeric>

#include "pmap/common/atomic_file.h"
#include "pmap/common/interrupt.h"
#include "pmap/common/progress.h"
#include "pmap/common/sha256.h"
#include "pmap/mapper/map_outputs.h"
#include "pmap/poses/poses_file.h"
#include "pmap/products/json_file.h"
#include "pmap/products/map_gltf.h"
#include "pmap/products/output_layout.h"
#include "pmap/products/planar_map_files.h"
#include "pmap/products/point_files.h"
#include "pmap/products/vrml.h"

namespace pmap::mapper {
namespace fs = std::filesystem;
using nlohmann::json;
using products::OutputLayout;

namespace {

json inputSummary(const MapperArgs& args, const InputResult& r) {
  const input::InputStats& st = r.stats;
  json in;
  in["file"] = args.cloud.empty() ? args.rawlog.string() : args.cloud.string();
  in["format"] = args.cloud.empty() ? input::toString(st.format) : "ply";
  in["records"] = st.records;
  in["observations"] = st.observations;
  in["pose_scans"] = st.pose_scans;
  in["structure_scans"] = st.structure_scans;
  in["odometry"] = st.odometry;
  in["images"] = st.images;
  in["structure_decimated"] = st.structure_decimated;
  in["invalid_timestamps"] = st.invalid_timestamps;
  in["non_finite_poses"] = st.non_finite_poses;
  if (st.aperture_replaced > 0) {
    in["pose_laser_aperture"] = {{"scans_replaced", st.aperture_replaced},
                                 {"file_deg", st.file_aperture_deg},
                                 {"used_deg", st.used_aperture_deg}};
  }
  in["leading_frame_skipped"] = st.leading_frame_skipped;
  in["ignored"] = st.ignored;
  in["truncated"] = !r.truncation.empty();
  if (!r.truncation.empty()) {
    in["truncation"] = r.truncation;
  }
  return in;
}

json historyJson(const std::vector<em::IterationRecord>& history) {
  json h = json::array();
  for (const em::IterationRecord& rec : history) {
    h.push_back({{"iteration", rec.iteration},
                 {"surfaces", rec.surfaces},
                 {"points", rec.points},
                 {"explained_fraction", rec.explained_fraction},
                 {"log_posterior", rec.log_posterior},
                 {"changes",
                  {{"removed", rec.changes.removed},
                   {"fused", rec.changes.fused},
                   {"split", rec.changes.split},
                   {"added", rec.changes.added}}}});
  }
  return h;
}

// Keys of the planar map (doc/outputs.md).
// p50 / p99 / max of a list of timings (nearest-rank percentiles).
json percentiles(std::vector<double> v) {
  if (v.empty()) {
    return {{"p50", nullptr}, {"p99", nullptr}, {"max", nullptr}};
  }
  std::sort(v.begin(), v.end());
  auto rank = [&](double q) {
    const auto k = static_cast<std::size_t>(std::ceil(q * static_cast<double>(v.size())));
    return v[std::min(v.size() - 1, k == 0 ? 0 : k - 1)];
  };
  return {{"p50", rank(0.5)}, {"p99", rank(0.99)}, {"max", v.back()}};
}

// The online map's repairs after loop closures (doc/outputs.md).
json repairSummary(const std::vector<OnlineRepair>& repairs) {
  std::size_t scans = 0;
  std::size_t points = 0;
  std::vector<double> ms;
  for (const OnlineRepair& r : repairs) {
    scans += r.scans;
    points += r.points;
    ms.push_back(r.ms);
  }
  return {{"count", repairs.size()},
          {"scans_moved", scans},
          {"points_moved", points},
          {"ms_total", std::accumulate(ms.begin(), ms.end(), 0.0)},
          {"ms", percentiles(ms)}};
}

// Each accepted loop closure: its keyframes' times, the match (the newer
// keyframe in the older one's frame), its score and what its solve did.
json closuresSummary(const std::vector<poses::LoopClosure>& closures) {
  json out = json::array();
  for (const poses::LoopClosure& c : closures) {
    out.push_back({{"older_t", c.older_t},
                   {"newer_t", c.t},
                   {"x_m", c.measurement.x},
                   {"y_m", c.measurement.y},
                   {"theta_deg", c.measurement.theta * 180.0 / M_PI},
                   {"score", c.score},
                   {"moved_m", c.moved_m},
                   {"solve_ms", c.solve_ms},
                   {"free_axis", {c.free_axis.x(), c.free_axis.y()}}});
  }
  return out;
}

// Online-mode keys: per-scan EM and pose timings (doc/outputs.md).
void addOnline(const std::vector<OnlineRecord>& online, json& s) {
  std::vector<double> em_ms;
  for (const OnlineRecord& rec : online) {
    em_ms.push_back(rec.em_ms);
  }
  s["em_per_scan_ms"] = percentiles(em_ms);
  json deciles = json::array();
  for (int d = 0; d < 10 && !em_ms.empty(); ++d) {
    const std::size_t a = em_ms.size() * static_cast<std::size_t>(d) / 10;
    const std::size_t b = em_ms.size() * static_cast<std::size_t>(d + 1) / 10;
    std::vector<double> part(em_ms.begin() + static_cast<std::ptrdiff_t>(a),
                             em_ms.begin() + static_cast<std::ptrdiff_t>(std::max(a + 1, b)));
    deciles.push_back(percentiles(part)["p50"]);
  }
  s["em_per_scan_ms_by_decile"] = deciles;
}

void writeOnlineCsv(const fs::path& path, const std::vector<OnlineRecord>& online) {
  writeFileAtomically(path, [&](std::ostream& out) {
    out << "scan,em_ms,surfaces,points,new_points,revisited,reassigned,active,added,removed,"
           "fused,split\n";
    for (const OnlineRecord& rec : online) {
      const em::OnlineUpdate& u = rec.update;
      out << rec.scan << "," << rec.em_ms << "," << rec.surfaces << "," << rec.points << ","
          << u.new_points << "," << u.revisited << "," << u.reassigned << "," << u.active_surfaces
          << "," << u.changes.added << "," << u.changes.removed << "," << u.changes.fused << ","
          << u.changes.split << "\n";
    }
  });
}

json refinementJson(const refine::RefineResult& r, const std::vector<em::Surface>& surfaces) {
  const refine::BoundaryResult& b = r.boundaries;
  json seams = json::array();
  for (const refine::Seam& s : b.seams) {
    seams.push_back({{"surface", surfaces[s.surface].id},
                     {"edge", s.edge},
                     {"other", surfaces[s.other].id},
                     {"distance_before_m", s.distance_m}});
  }
  json openings = json::array();
  for (const refine::Opening& o : r.openings.openings) {
    openings.push_back({{"door", o.door_id},
                        {"wall", o.wall_id},
                        {"edges", o.edges},
                        {"max_move_m", o.max_move_m}});
  }
  return {{"ran", r.ran},
          {"message", r.message},
          {"fused_pairs", r.fusion.changed_pairs},
          {"fused_replaced_ids", r.fusion.replaced_ids},
          {"fused_new_ids", r.fusion.new_ids},
          {"seams", seams},
          {"manhattan_pairs", b.manhattan_pairs},
          {"termination", b.termination},
          {"iterations", b.iterations},
          {"initial_cost", b.initial_cost},
          {"final_cost", b.final_cost},
          {"reverted_ids", b.reverted_ids},
          {"openings", openings},
          {"fusion_s", r.fusion_s},
          {"solve_s", r.solve_s}};
}

void addPlanarMap(const PlanarResult& planar, std::size_t raw_triangles, json& s) {
  const em::PlanarMap& map = planar.map;
  const std::size_t map_triangles = 2 * map.surfaces.size() + map.fine_triangles.size();
  s["surfaces"] = map.surfaces.size();
  s["fine_triangles"] = map.fine_triangles.size();
  s["explained_fraction"] = map.explained_fraction;
  s["map_triangles"] = map_triangles;
  s["compression"] = map_triangles > 0
                         ? static_cast<double>(raw_triangles) / static_cast<double>(map_triangles)
                         : 0.0;
  // Offline: the EM's iterations and how it ended; online: the scans fed.
  const int iterations =
      planar.offline ? planar.offline->iterations : static_cast<int>(planar.online.size());
  s["iterations"] = iterations;
  s["termination"] = planar.offline ? em::toString(planar.offline->termination) : "online";
  if (planar.offline && planar.offline->blocks > 0) {
    s["blocks"] = planar.offline->blocks;
    s["blocks_unconverged"] = planar.offline->blocks_unconverged;
  }
  s["em_message"] = planar.message;
  s["ms_per_iteration"] =
      iterations > 0 ? 1000.0 * s["timing_s"]["em"].get<double>() / iterations : 0.0;
  s["history"] =
      historyJson(planar.offline ? planar.offline->history : std::vector<em::IterationRecord>{});
  if (!planar.online.empty()) {
    addOnline(planar.online, s);
  }
  if (planar.refine) {
    s["refinement"] = refinementJson(*planar.refine, map.surfaces);
  }
}

// Every stage's exclusive wall time; they add up to "total" (the run so far).
json timingJson(const StageClock& clock) {
  json t;
  double total = 0;
  for (std::size_t i = 0; i < static_cast<std::size_t>(Stage::kCount); ++i) {
    const double seconds = clock.seconds(static_cast<Stage>(i));
    t[stageKey(static_cast<Stage>(i))] = seconds;
    total += seconds;
  }
  t["total"] = total;
  return t;
}

json summaryJson(const MapperArgs& args, const MappingResult& r, const StageClock& clock) {
  const PoseResult& poses = r.poses;
  const PointsResult& points = r.points;
  json s;
  s["timing_s"] = timingJson(clock);
  const json& t = s["timing_s"];
  const double processing_s = t["read"].get<double>() + t["pose"].get<double>() +
                              t["map"].get<double>() + t["em"].get<double>() +
                              t["refine"].get<double>();
  s["input"] = inputSummary(args, r.input);
  s["scans"] = points.placement.placed;
  s["scans_without_pose"] = points.placement.without_pose;
  s["measurements"] = r.input.measurements;
  s["points"] = points.map.size();
  const input::DropCounts& dropped = r.input.dropped;
  s["points_dropped"] = dropped.total();
  s["points_dropped_by_reason"] = {{"invalid", dropped.invalid},
                                   {"non_finite", dropped.non_finite},
                                   {"out_of_range", dropped.out_of_range}};
  s["raw_triangles"] = points.raw_triangles.size();
  s["poses"] = {{"source", toString(poses.source)},
                {"count", poses.trajectory.size()},
                {"scans_matched", poses.stats.scans_matched},
                {"odometry_readings", poses.stats.odometry_readings},
                {"non_monotonic", poses.stats.non_monotonic},
                {"actions_timed_by_frame", poses.stats.actions_timed_by_frame},
                {"actions_without_time", poses.stats.actions_without_time},
                {"implausible_dropped", poses.motion.dropped()},
                {"implausible_by_reason",
                 {{"non_finite", poses.motion.non_finite},
                  {"beyond_max_coordinate", poses.motion.too_far},
                  {"step_beyond_limits", poses.motion.too_fast}}},
                {"odometry_resets", poses.motion.resets}};
  if (poses.loops) {
    const poses::LoopClosureStats& l = *poses.loops;
    s["poses"]["loop_closure"] = {{"keyframes", l.keyframes},
                                  {"refined_edges", l.refined_edges},
                                  {"refined_scans", l.refined_scans},
                                  {"odometry_keyframes", l.odometry_keyframes},
                                  {"candidates", l.candidates},
                                  {"rejected_by_score", l.rejected_match},
                                  {"rejected_as_ambiguous", l.rejected_ambiguous},
                                  {"rejected_by_free_space", l.rejected_free_space},
                                  {"verified_along_a_line_free", l.axis_only},
                                  {"rejected_by_chi2", l.rejected_chi2},
                                  {"accepted", l.accepted},
                                  {"path_constraints", l.path_constraints},
                                  {"path_constraints_rejected", l.path_constraints_rejected},
                                  {"search_s", l.search_s},
                                  {"solve_s", l.solve_s},
                                  {"wait_s", l.wait_s},
                                  {"trajectory_rewrites", poses.corrections},
                                  {"front_map_rebuilds", poses.front_map_rebuilds},
                                  {"structure_scans_moved", points.scans_moved}};
    s["poses"]["loop_closure"]["closures"] = closuresSummary(poses.closures);
    if (const auto& c = poses.odometry_calibration) {
      s["poses"]["loop_closure"]["odometry_calibration"] = {
          {"edges", c->edges},
          {"scale", c->scale},
          {"scale_sigma", std::sqrt(c->covariance(0, 0))},
          {"turn_scale", c->turn},
          {"turn_scale_sigma", std::sqrt(c->covariance(1, 1))},
          {"drift_deg_per_m", c->drift_rad_per_m * 180.0 / M_PI},
          {"drift_sigma_deg_per_m", std::sqrt(c->covariance(2, 2)) * 180.0 / M_PI}};
    }
    if (r.planar && !r.planar->repairs.empty()) {
      s["poses"]["loop_closure"]["online_repairs"] = repairSummary(r.planar->repairs);
    }
  }
  for (const refine::PlanePoseResult& p : poses.plane_rounds) {
    s["poses"]["plane_refinement"].push_back({{"ran", p.ran},
                                              {"knots", p.knots},
                                              {"surfaces", p.surfaces},
                                              {"residuals", p.residuals},
                                              {"iterations", p.iterations},
                                              {"initial_cost", p.initial_cost},
                                              {"final_cost", p.final_cost},
                                              {"max_shift_m", p.max_shift_m},
                                              {"max_turn_deg", p.max_turn_deg},
                                              {"seconds", p.seconds},
                                              {"termination", p.termination}});
  }
  if (poses.laser_maps) {
    const poses::GridInfo& g = poses.laser_maps->info;
    s["poses"]["grid"] = {{"resolution_m", g.resolution_m},
                          {"x_min_m", g.x_min},
                          {"x_max_m", g.x_max},
                          {"y_min_m", g.y_min},
                          {"y_max_m", g.y_max},
                          {"cols", g.cols},
                          {"rows", g.rows},
                          {"scans", g.scans},
                          {"scans_unplaced", g.scans_unplaced}};
  }
  s["duration_s"] = r.input.duration();
  s["mode"] = toString(r.kind);
  if (!r.mode_note.empty()) {
    s["mode_note"] = r.mode_note;
  }
  s["warnings"] = r.warnings;
  if (const auto& e = r.sigma_estimate) {
    s["sigma_estimate"] = {{"sigma_m", e->sigma_m},
                           {"estimated", e->estimated},
                           {"samples", e->samples},
                           {"p25_m", e->p25_m},
                           {"p75_m", e->p75_m}};
  }
  s["pose_per_scan_ms"] = percentiles(poses.step_ms);
  if (r.planar) {
    addPlanarMap(*r.planar, points.raw_triangles.size(), s);
  }
  // One definition everywhere: recorded duration / wall time of reading,
  // poses and mapping (points, raw map, EM and refinement; textures and
  // writing excluded). A single
  // frame has no duration: no factor (null).
  const double duration = r.input.duration();
  s["realtime_factor"] =
      processing_s > 0 && duration > 0 ? json(duration / processing_s) : json(nullptr);
  return s;
}

void writeRawMap(const fs::path& path, const PointsResult& r) {
  products::VrmlMesh mesh;
  mesh.name = "RawMap";
  mesh.vertices = r.map.xyz();
  mesh.triangles = r.raw_triangles;
  mesh.color = {0.75, 0.75, 0.7};
  products::writeVrml(path, {mesh},
                      "planar-mapper raw map: " + std::to_string(r.raw_triangles.size()) +
                          " triangles from neighbouring beams of consecutive scans");
}

/// raw.glb: the raw map's geometry alone as glTF binary (its triangles as the
/// fine-triangle mesh, only the vertices they use), the size the baselines
/// compare (doc/outputs.md).
void writeRawMapGlb(const fs::path& path, const PointsResult& r) {
  products::MapModel model;
  std::vector<std::uint32_t> slot(r.map.size(), UINT32_MAX);
  for (const auto& t : r.raw_triangles) {
    std::array<std::uint32_t, 3> out{};
    for (int k = 0; k < 3; ++k) {
      if (slot[t[k]] == UINT32_MAX) {
        slot[t[k]] = static_cast<std::uint32_t>(model.fine.vertices.size());
        model.fine.vertices.push_back(r.map.xyz()[t[k]]);
      }
      out[k] = slot[t[k]];
    }
    model.fine.triangles.push_back(out);
  }
  model.fine.color = {0.75, 0.75, 0.7};
  products::writeMapGlb(path, model, /*with_textures=*/false);
}

}  // namespace

void writeOutputs(const MapperConfig& config, const MapperArgs& args, const MappingResult& r,
                  const MapProducts* products, StageClock& clock, const fs::path& dir) {
  auto in_write = clock.enter(Stage::kWrite);
  ProgressLine progress("planar-mapper: writing", ProgressOptions{!args.quiet, 1.0, true});
  using L = OutputLayout;
  writeTextFileAtomically(dir / L::kEffectiveIni,
                          config.effective->toIniText({"effective configuration of planar-mapper",
                                                       "source: " + config.doc.origin()}));
  if (!r.poses.trajectory.empty()) {
    poses::writePosesFile(dir / L::kPosesTxt, r.poses.trajectory);
    poses::writeTumFile(dir / L::kPosesTum, r.poses.trajectory);
  }
  if (r.poses.graph) {
    poses::writeGraphFile(dir / L::kPosesGraph, *r.poses.graph);
  }
  if (r.poses.laser_maps) {
    poses::writeGridPng((dir / L::kGridPng).string(), r.poses.laser_maps->grid);
    poses::writeGridMap((dir / L::kGridMap).string(), r.poses.laser_maps->grid);
    poses::writeSimpleMap((dir / L::kSimpleMap).string(), r.poses.laser_maps->simplemap);
  }
  throwIfInterrupted();
  if (!args.poses_only) {
    products::writeScansCsv(dir / L::kScansCsv, r.points.map);
    products::writePointsPly(
        dir / L::kPointsPly, r.points.map,
        r.planar ? products::surfaceIdsOfPoints(r.planar->map) : std::vector<int>{});
    throwIfInterrupted();
    if (config.output.raw_map) {
      writeRawMap(dir / L::kRawWrl, r.points);
      writeRawMapGlb(dir / L::kRawGlb, r.points);
      throwIfInterrupted();
    }
    if (r.planar && !r.planar->online.empty()) {
      writeOnlineCsv(dir / L::kOnlineCsv, r.planar->online);
    }
    if (r.planar) {
      products::writeSurfacesCsv(dir / L::kSurfacesCsv, r.planar->map.surfaces);
    }
    if (products != nullptr) {
      writeMapFiles(dir, args.out.filename().string(), *products, r, config.output);
    }
  }
  json summary = summaryJson(args, r, clock);
  if (products != nullptr) {
    summary["texture"] = textureSummary(config, *products);
    summary["report_warnings"] = writeReportFiles(dir, *products, r, summary);
    summary["timing_s"] = timingJson(clock);  // the report included
  }
  products::writeJsonFile(dir / L::kSummary, summary);
  progress.finish();
}

products::OutputManifest manifestHeader(const MapperConfig& config,
                                        const std::vector<std::string>& command) {
  products::OutputManifest m;
  m.program = std::string("planar-mapper ") + PMAP_VERSION;
  m.command = command;
  m.config_sha256 = sha256Hex(config.effective->toIniText());
  m.written_utc = products::utcNow();
  return m;
}

}  // namespace pmap::mapper
