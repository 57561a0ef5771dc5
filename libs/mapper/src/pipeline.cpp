#include "pmap/mapper/pipeline.h"

#include <cstdio>

#include "pmap/common/error.h"
#include "pmap/common/progress.h"
#include "pmap/input/ply_cloud.h"
#include "pmap/points/neighbour_graph.h"
#include "rawlog_run.h"

namespace pmap::mapper {
namespace {

MappingResult runCloud(const MapperArgs& args, StageClock& clock) {
  MappingResult result;
  input::StructureScan scan;
  {
    auto in_read = clock.enter(Stage::kRead);
    scan = input::readPlyCloud(args.cloud);
  }
  result.poses.source = PoseSource::kCloud;
  result.input.dropped = scan.dropped;
  result.input.measurements = scan.measurements();
  if (scan.points.empty()) {
    throw InputError(args.cloud.string() + ": no finite points");
  }
  auto in_map = clock.enter(Stage::kMap);
  result.points.map.addScan(scan, mrpt::math::TPose3D());
  result.points.placement.placed = 1;
  result.input.stats.structure_scans = 1;
  return result;
}

points::NeighbourGraph graphOf(const MapperConfig& config, const MappingResult& result) {
  return points::neighbourGraph(result.points.map, config.planar_em.cloud_neighbour_radius_m,
                                config.planar_em.em.threads);
}

PlanarResult runOfflineEm(const MapperConfig& config, const MapperArgs& args,
                          const points::NeighbourGraph& graph, const points::PointMap& map) {
  ProgressLine progress("planar-mapper: EM", ProgressOptions{!args.quiet, 1.0, false});
  em::OfflineEm em(config.planar_em.em);
  const int max_iterations = em.iterationCap(map.size());
  const bool in_blocks = em.inBlocks(map.size());  // one line per block mapped
  em.setObserver([&](const em::IterationRecord& rec) {
    char detail[96];
    std::snprintf(detail, sizeof detail, "%s%d surfaces, %.1f %% explained",
                  in_blocks ? "blocks; the last: " : "", rec.surfaces,
                  100.0 * rec.explained_fraction);
    progress.update(static_cast<std::uint64_t>(rec.iteration + 1),
                    static_cast<std::uint64_t>(max_iterations), detail);
  });
  em::EmResult r = em.run(map.xyz(), graph.neighbours, graph.rows);
  progress.finish(r.message);
  PlanarResult planar;
  planar.map = std::move(r.map);
  planar.message = r.message;
  planar.offline =
      OfflineRun{r.termination, r.iterations, std::move(r.history), r.blocks, r.blocks_unconverged};
  return planar;
}

// Each point's sensor origin (the side a surface was seen from).
std::vector<Eigen::Vector3d> sensorOrigins(const points::PointMap& map) {
  std::vector<Eigen::Vector3d> out(map.size());
  for (const points::ScanRecord& s : map.scans()) {
    const Eigen::Vector3d o(s.sensor_pose.x, s.sensor_pose.y, s.sensor_pose.z);
    std::fill_n(out.begin() + static_cast<std::ptrdiff_t>(s.first_point), s.num_points, o);
  }
  return out;
}

// Fusion and the Ceres refinement of the EM's map (offline or online).
void runRefinement(const MapperConfig& config, const MapperArgs& args,
                   const points::NeighbourGraph& graph, const points::PointMap& map,
                   PlanarResult& planar) {
  ProgressLine progress("planar-mapper: refinement", ProgressOptions{!args.quiet, 1.0, true});
  planar.refine = refine::refineMap(
      map.xyz(), graph.neighbours, graph.rows, config.planar_em.em, config.refine, planar.map,
      config.refine.openings ? sensorOrigins(map) : std::vector<Eigen::Vector3d>{});
  if (planar.refine->fusion.changed_pairs > 0) {
    planar.message +=
        "; refinement fused " + std::to_string(planar.refine->fusion.changed_pairs) + " pairs";
  }
  progress.finish(planar.refine->message);
}

// sigma_m = auto for the offline EM: estimated from all the placed points
// (noise_estimate.h). Too few points, or an estimate that is no valid
// sigma_m (z_max_m must exceed 3 sigma), keep the configured value.
void resolveAutoSigma(MapperConfig& config, StageClock& clock, MappingResult& result) {
  em::PlanarEmOptions& em = config.planar_em.em;
  if (!em.sigma_auto) {
    return;
  }
  auto in_em = clock.enter(Stage::kEm);
  result.sigma_estimate = em::estimateSigmaInto(em, result.points.map.xyz());
}

// The offline EM over the points as they are placed now.
void mapOffline(const MapperConfig& config, const MapperArgs& args, StageClock& clock,
                MappingResult& result, std::optional<points::NeighbourGraph>& graph) {
  auto in_em = clock.enter(Stage::kEm);
  graph = graphOf(config, result);
  result.planar = runOfflineEm(config, args, *graph, result.points.map);
}

// The refinement of the planar map (offline or online), unless turned off.
void refineMap(const MapperConfig& config, const MapperArgs& args, StageClock& clock,
               MappingResult& result, std::optional<points::NeighbourGraph>& graph) {
  if (!result.planar || !config.refine.enabled || args.no_refine) {
    return;
  }
  auto in_refine = clock.enter(Stage::kRefine);
  if (!graph) {
    graph = graphOf(config, result);
  }
  runRefinement(config, args, *graph, result.points.map, *result.planar);
}

// Planes correct poses (plane_poses.h): each round fits the corrections to
// the map's vertical surfaces, moves the scans and the trajectory, and maps
// the moved points afresh (the offline EM and the refinement); the laser
// grid follows the moved trajectory.
void correctPosesWithPlanes(const MapperConfig& config, const MapperArgs& args, StageClock& clock,
                            MappingResult& result, std::optional<points::NeighbourGraph>& graph) {
  const refine::PlanePoseOptions& options = config.plane_poses;
  const points::PointMap placed = result.points.map;  // as the pose stage placed them
  const poses::Trajectory trajectory = result.poses.trajectory;
  refine::PoseCorrection correction;
  for (int round = 0; round < options.rounds; ++round) {
    refine::PlanePoseResult fit;
    {
      auto in_poses = clock.enter(Stage::kPoses);
      fit = refine::fitPosesToPlanes(placed, result.planar->map, options, correction);
      if (fit.ran) {
        correction = fit.correction;
        result.points.map = placed;
        result.poses.trajectory = trajectory;
        refine::applyCorrection(correction, result.points.map, result.poses.trajectory);
      }
    }
    const bool ran = fit.ran;
    result.poses.plane_rounds.push_back(std::move(fit));
    if (!ran) {
      break;  // the last round's correction stands
    }
    mapOffline(config, args, clock, result, graph);
    refineMap(config, args, clock, result, graph);
  }
  if (result.poses.laser_log && !correction.empty()) {
    auto in_poses = clock.enter(Stage::kPoses);
    result.poses.laser_maps = poses::buildLaserMaps(
        *result.poses.laser_log, result.poses.trajectory, config.sensors.max_pose_gap_s);
  }
}

// What runs after the points: the offline EM (also online's fallback for
// range images and unorganised clouds, which have no scan-line order), or
// nothing.
RunKind kindAfterPoints(const MapperArgs& args, const MappingResult& result) {
  if (args.poses_only) {
    return RunKind::kPosesOnly;
  }
  if (args.mode == MapMode::kRaw) {
    return RunKind::kRaw;
  }
  return result.planar ? RunKind::kOnline : RunKind::kOffline;
}

}  // namespace

MappingResult runPipeline(const MapperConfig& given, const MapperArgs& args, StageClock& clock,
                          LiveView* live) {
  MappingResult result;
  if (!args.cloud.empty()) {
    result = runCloud(args, clock);
  } else {
    runRawlog(given, args, clock, live, result);
  }
  result.kind = kindAfterPoints(args, result);
  MapperConfig config = given;  // with sigma_m = auto resolved
  std::optional<points::NeighbourGraph> graph;
  if (result.kind == RunKind::kOffline) {
    resolveAutoSigma(config, clock, result);
    mapOffline(config, args, clock, result, graph);
  } else if (result.sigma_estimate && result.sigma_estimate->estimated) {
    config.planar_em.em.sigma_m = result.sigma_estimate->sigma_m;  // the online EM's
  }
  refineMap(config, args, clock, result, graph);
  if (result.kind == RunKind::kOffline && config.plane_poses.enabled &&
      result.poses.source != PoseSource::kCloud && result.poses.source != PoseSource::kIdentity) {
    correctPosesWithPlanes(config, args, clock, result, graph);
  } else if (config.plane_poses.enabled && result.kind == RunKind::kOnline) {
    result.warnings.push_back(
        "[Poses] plane_refinement runs with --mode offline only: this online run did not use it");
  }
  noteNothingFound(args, result);
  noteUnconverged(config, result);
  return result;
}

void noteUnconverged(const MapperConfig& config, MappingResult& result) {
  if (!result.planar || !result.planar->offline ||
      result.planar->offline->termination != em::Termination::kMaxIterations) {
    return;
  }
  char explained[32];
  std::snprintf(explained, sizeof explained, "%.1f %%",
                100.0 * result.planar->map.explained_fraction);
  const OfflineRun& run = *result.planar->offline;
  const std::string where = run.blocks > 0 ? " in " + std::to_string(run.blocks_unconverged) +
                                                 " of its " + std::to_string(run.blocks) +
                                                 " spatial blocks before they converged"
                                           : " before it converged";
  result.warnings.push_back(
      "the offline EM stopped at [PlanarEM] max_iterations (" +
      std::to_string(config.planar_em.em.max_iterations) + ")" + where +
      ": its model selection may be unfinished (" + explained +
      " explained); raise max_iterations, or set coarse_points, or block_points for a large "
      "cloud (doc/cloud-scaling.md)");
}

void noteNothingFound(const MapperArgs& args, MappingResult& result) {
  if (args.poses_only) {
    return;
  }
  const std::string input = args.cloud.empty() ? args.rawlog.string() : args.cloud.string();
  const points::PointMap& map = result.points.map;
  if (map.size() == 0) {
    result.warnings.push_back("nothing found: " + input + ": none of the " +
                              std::to_string(result.input.measurements) +
                              " structure measurements is a valid point (" +
                              std::to_string(result.input.dropped.total()) +
                              " dropped: invalid, non-finite or out of range); the outputs are "
                              "valid and empty");
  } else if (result.planar && result.planar->map.surfaces.empty()) {
    result.warnings.push_back("nothing found: " + input + ": no planar surface among the " +
                              std::to_string(map.size()) +
                              " points; the map holds fine triangles only");
  }
}

}  // namespace pmap::mapper
