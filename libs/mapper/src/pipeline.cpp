#include "pmap/mapper/pipeline.h"

#include <mrpt/system/datetime.h>

#include <algorithm>
#include <chrono>

#include "pmap/common/error.h"
#include "pmap/common/progress.h"
#include "pmap/config/strict_mrpt_config.h"
#include "pmap/input/label_inventory.h"
#include "pmap/input/ply_cloud.h"
#include "pmap/input/rawlog_reader.h"
#include "pmap/points/neighbour_graph.h"
#include "pmap/points/raw_mesh.h"
#include "pmap/poses/pose_stage.h"
#include "pmap/poses/poses_file.h"

namespace pmap::mapper {
namespace {

using Clock = std::chrono::steady_clock;  // per-scan pose timings
double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

class RawlogRun {
 public:
  RawlogRun(const MapperConfig& config, const MapperArgs& args, MappingResult& result,
            StageClock& clock, LiveView* live)
      : config_(config),
        args_(args),
        result_(result),
        clock_(clock),
        live_(live),
        online_(args.mode == "online" && !args.poses_only
                    ? std::make_unique<OnlineStage>(config.planar_em.em, config.online_em, args.out,
                                                    args.snapshot_every)
                    : nullptr),
        mesh_(config.output.raw_mesh),
        placer_(
            result.map, config.sensors.max_pose_gap_s,
            [this](const input::StructureScan& s, std::size_t record) { onPlaced(s, record); }) {}

  void run() {
    checkLabels();
    poses::PoseStage stage = makePoseStage();
    result_.pose_source = stage.source();
    input::RawlogReaderOptions reader_options;
    reader_options.accept_truncated = args_.accept_truncated;
    input::RawlogReader reader(args_.rawlog, reader_options);
    input::ObservationSource source(reader, input::RoleClassifier(config_.sensors),
                                    args_.selection);
    ProgressLine progress("planar-mapper: reading", !args_.quiet);
    Pacer pacer(args_.playback_rate);
    input::InputStep step;
    for (;;) {
      bool more = false;
      {
        auto in_read = clock_.enter(Stage::kRead);
        more = source.next(step);
      }
      if (!more) {
        break;
      }
      if (!step.observations.empty()) {
        pacer.waitFor(mrpt::Clock::toDouble(step.observations.front().obs->timestamp));
      }
      processPoses(stage, step);
      {
        auto in_map = clock_.enter(Stage::kMap);
        collect(step);
        placer_.drain(stage.trajectory(), stage.fixed());
      }
      progress.update(reader.compressedPosition(), reader.fileSize(), progressDetail(stage));
    }
    {
      auto in_map = clock_.enter(Stage::kMap);
      finish(stage, source);
    }
    progress.finish(progressDetail(stage));
    result_.truncation = reader.truncationMessage();
  }

 private:
  // The pose stage: ICP, or the given poses (checked against the motion
  // limits like odometry).
  poses::PoseStage makePoseStage() const {
    auto tracker = makeIcpTracker(config_);  // validates the ICP sections in every mode
    if (args_.poses.empty()) {
      return poses::PoseStage(std::move(tracker), config_.motion);
    }
    return poses::PoseStage(poses::readPosesFile(args_.poses), config_.motion);
  }

  // The roles this run uses must name labels the file has (label_inventory.h).
  void checkLabels() {
    input::RolesInUse used;
    used.pose_laser = used.odometry = args_.poses.empty();
    used.structure = !args_.poses_only;
    used.cameras = !args_.poses_only && !args_.no_textures && config_.texture.enabled;
    const input::LabelInventory inventory =
        input::scanLabels(args_.rawlog, input::kLabelCheckRecords);
    for (std::string& w : input::checkRoleLabels(config_.sensors, used, args_.selection.keep_labels,
                                                 inventory, config_.doc.origin())) {
      result_.warnings.push_back(std::move(w));
    }
  }

  void processPoses(poses::PoseStage& stage, const input::InputStep& step) {
    const auto t0 = Clock::now();
    {
      auto in_poses = clock_.enter(Stage::kPoses);
      stage.process(step, args_.rawlog.string());
    }
    if (carriesPoses(step)) {
      result_.pose_step_ms.push_back(1000.0 * since(t0));
    }
  }

  std::string progressDetail(const poses::PoseStage& stage) const {
    const std::string poses = std::to_string(stage.trajectory().size()) + " poses";
    if (args_.poses_only) {
      return poses;
    }
    return poses + ", " + std::to_string(placer_.stats().placed) + " structure scans, " +
           std::to_string(result_.map.size()) + " points";
  }

  void collect(const input::InputStep& step) {
    for (const auto& item : step.observations) {
      const double t = mrpt::Clock::toDouble(item.obs->timestamp);
      result_.first_time = seen_any_ ? std::min(result_.first_time, t) : t;
      result_.last_time = seen_any_ ? std::max(result_.last_time, t) : t;
      seen_any_ = true;
      if (item.roles.camera && !args_.poses_only && !args_.no_textures) {
        if (auto img = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(item.obs)) {
          result_.images.push_back(std::move(img));
        }
      }
      if (item.roles.structure && !args_.poses_only) {
        input::StructureScan scan = input::extractStructureScan(*item.obs, item.structure_index);
        result_.dropped += scan.dropped;
        result_.measurements += scan.measurements();
        placer_.add(std::move(scan));
      }
    }
  }

  // Steps that carry a pose-laser scan: their pose-stage time is the "pose
  // per scan" time (ICP and pose handling) of summary.json.
  static bool carriesPoses(const input::InputStep& step) {
    return std::any_of(step.observations.begin(), step.observations.end(),
                       [](const input::ObservationItem& o) { return o.roles.pose_laser; });
  }

  void onPlaced(const input::StructureScan& scan, std::size_t record) {
    if (config_.output.raw_map) {
      mesh_.addScan(result_.map, record, scan.rows, scan.cols, scan.organised);
    }
    if (online_ && scan.organised) {
      auto in_em = clock_.enter(Stage::kEm);
      online_->addScan(result_.map, record);
    } else if (online_) {
      unorganised_ = true;
    }
    if (live_ != nullptr && live_->due()) {
      const std::optional<em::PlanarMap> planar =
          online_ && !unorganised_ ? std::optional<em::PlanarMap>(online_->map()) : std::nullopt;
      live_->update(result_.map, record, planar ? &*planar : nullptr);
    }
  }

  void finish(poses::PoseStage& stage, const input::ObservationSource& source) {
    result_.input = source.stats();
    result_.pose_stats = stage.stats();
    const auto& in = result_.input;
    const bool no_pose_source = in.pose_scans == 0 && in.odometry == 0 && args_.poses.empty();
    if (no_pose_source && placer_.pending() == 1) {
      result_.pose_source = "identity";  // a single 3D frame: its own frame is the world
      placer_.placeAllAt(mrpt::math::TPose3D());
    } else if (no_pose_source && placer_.pending() > 1) {
      throw InputError(args_.rawlog.string() + ": " + std::to_string(placer_.pending()) +
                       " structure scans but no pose source (no odometry, no pose laser; "
                       "give --poses FILE)");
    }
    placer_.drain(stage.trajectory(), true);
    result_.trajectory = stage.trajectory();
    result_.motion = stage.gate().stats();
    const std::string dropped = stage.gate().summary(
        args_.poses.empty() ? "odometry readings or increments" : "given poses");
    if (!dropped.empty()) {
      result_.warnings.push_back(args_.rawlog.string() + ": " + dropped);
    }
    result_.placement = placer_.stats();
    result_.raw_triangles = mesh_.triangles();
    checkUsable();
    if (online_ && !unorganised_) {
      result_.em_mode = "online";
      result_.online = online_->history();
      em::EmResult em;
      em.map = online_->map();
      em.termination = em::Termination::kOnline;
      em.iterations = static_cast<int>(result_.online.size());
      em.message = "online over " + std::to_string(em.iterations) + " scans, " +
                   std::to_string(em.map.surfaces.size()) + " surfaces";
      result_.em = std::move(em);
    }
  }

  void checkUsable() const {
    const auto& in = result_.input;
    const std::string file = args_.rawlog.string();
    if (in.pose_scans == 0 && in.structure_scans == 0) {
      throw InputError(file + ": no usable scans (" + std::to_string(in.records) + " records, " +
                       std::to_string(in.observations) +
                       " observations; check the [Sensors] labels and the selection)");
    }
    if (args_.poses_only) {
      if (result_.trajectory.empty()) {
        throw InputError(file + ": no poses computed (no odometry or pose-laser scans)");
      }
      return;
    }
    if (in.structure_scans == 0) {
      throw InputError(file +
                       ": no structure observations (labels in [Sensors] structure); "
                       "use --poses-only to compute poses only");
    }
    if (result_.placement.placed == 0) {
      throw InputError(file + ": none of the " + std::to_string(in.structure_scans) +
                       " structure scans has a pose (check timestamps and --poses)");
    }
  }

  const MapperConfig& config_;
  const MapperArgs& args_;
  MappingResult& result_;
  StageClock& clock_;
  LiveView* live_;
  std::unique_ptr<OnlineStage> online_;
  bool unorganised_ = false;
  points::RawMeshBuilder mesh_;
  points::ScanPlacer placer_;
  bool seen_any_ = false;
};

MappingResult runCloud(const MapperArgs& args, StageClock& clock) {
  MappingResult result;
  input::StructureScan scan;
  {
    auto in_read = clock.enter(Stage::kRead);
    scan = input::readPlyCloud(args.cloud);
  }
  result.pose_source = "cloud";
  result.dropped = scan.dropped;
  result.measurements = scan.measurements();
  if (scan.points.empty()) {
    throw InputError(args.cloud.string() + ": no finite points");
  }
  auto in_map = clock.enter(Stage::kMap);
  result.map.addScan(scan, mrpt::math::TPose3D());
  result.placement.placed = 1;
  result.input.structure_scans = 1;
  return result;
}

points::NeighbourGraph graphOf(const MapperConfig& config, const MappingResult& result) {
  return points::neighbourGraph(result.map, config.planar_em.cloud_neighbour_radius_m);
}

void runEm(const MapperConfig& config, const MapperArgs& args, const points::NeighbourGraph& graph,
           MappingResult& result) {
  ProgressLine progress("planar-mapper: EM", ProgressOptions{!args.quiet, 1.0, false});
  em::OfflineEm em(config.planar_em.em);
  const int max_iterations = config.planar_em.em.max_iterations;
  em.setObserver([&](const em::IterationRecord& rec) {
    char detail[96];
    std::snprintf(detail, sizeof detail, "%d surfaces, %.1f %% explained", rec.surfaces,
                  100.0 * rec.explained_fraction);
    progress.update(static_cast<std::uint64_t>(rec.iteration + 1),
                    static_cast<std::uint64_t>(max_iterations), detail);
  });
  result.em = em.run(result.map.xyz(), graph.neighbours, graph.rows);
  progress.finish(result.em->message);
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
                   const points::NeighbourGraph& graph, MappingResult& result) {
  ProgressLine progress("planar-mapper: refinement", ProgressOptions{!args.quiet, 1.0, true});
  result.refine = refine::refineMap(
      result.map.xyz(), graph.neighbours, graph.rows, config.planar_em.em, config.refine,
      result.em->map,
      config.refine.openings ? sensorOrigins(result.map) : std::vector<Eigen::Vector3d>{});
  if (result.refine->fusion.changed_pairs > 0) {
    result.em->message +=
        "; refinement fused " + std::to_string(result.refine->fusion.changed_pairs) + " pairs";
  }
  progress.finish(result.refine->message);
}

}  // namespace

MappingResult runPipeline(const MapperConfig& config, const MapperArgs& args, StageClock& clock,
                          LiveView* live) {
  MappingResult result;
  if (!args.cloud.empty()) {
    result = runCloud(args, clock);
  } else {
    RawlogRun(config, args, result, clock, live).run();
  }
  const bool online_done = result.em_mode == "online";
  std::optional<points::NeighbourGraph> graph;
  if (!args.poses_only && (args.mode == "offline" || (args.mode == "online" && !online_done))) {
    result.em_mode = "offline";  // online falls back for unorganised clouds
    auto in_em = clock.enter(Stage::kEm);
    graph = graphOf(config, result);
    runEm(config, args, *graph, result);
  } else if (args.mode == "raw" || args.poses_only) {
    result.em_mode = args.poses_only ? "poses-only" : "raw";
  }
  if (result.em && config.refine.enabled && !args.no_refine) {
    auto in_refine = clock.enter(Stage::kRefine);
    if (!graph) {
      graph = graphOf(config, result);
    }
    runRefinement(config, args, *graph, result);
  }
  noteNothingFound(args, result);
  return result;
}

void noteNothingFound(const MapperArgs& args, MappingResult& result) {
  if (args.poses_only) {
    return;
  }
  const std::string input = args.cloud.empty() ? args.rawlog.string() : args.cloud.string();
  if (result.map.size() == 0) {
    result.warnings.push_back(
        "nothing found: " + input + ": none of the " + std::to_string(result.measurements) +
        " structure measurements is a valid point (" + std::to_string(result.dropped.total()) +
        " dropped: invalid, non-finite or out of range); the outputs are valid and empty");
  } else if (result.em && result.em->map.surfaces.empty()) {
    result.warnings.push_back("nothing found: " + input + ": no planar surface among the " +
                              std::to_string(result.map.size()) +
                              " points; the map holds fine triangles only");
  }
}

}  // namespace pmap::mapper
