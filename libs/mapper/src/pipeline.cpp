#include "pmap/mapper/pipeline.h"

#include <mrpt/system/datetime.h>

#include <algorithm>
#include <chrono>

#include "pmap/common/error.h"
#include "pmap/common/progress.h"
#include "pmap/config/strict_mrpt_config.h"
#include "pmap/input/ply_cloud.h"
#include "pmap/input/rawlog_reader.h"
#include "pmap/points/neighbour_graph.h"
#include "pmap/points/raw_mesh.h"
#include "pmap/poses/pose_stage.h"
#include "pmap/poses/poses_file.h"

namespace pmap::mapper {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// ICP tracker configured from [ICP] / [MappingApplication*]; every key
/// there must be read by MRPT's loaders.
std::unique_ptr<poses::IcpPoseTracker> makeTracker(const MapperConfig& config) {
  config::StrictMrptConfig mrpt_config(config.doc, mrptSections(), config.effective.get());
  mrpt_config.requireSection("ICP");
  mrpt_config.requireSection("MappingApplication");
  std::unique_ptr<poses::IcpPoseTracker> tracker;
  try {
    tracker = std::make_unique<poses::IcpPoseTracker>(mrpt_config);
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    mrpt_config.throwLoaderError(e);
  }
  mrpt_config.checkAllRead();
  return tracker;
}

class RawlogRun {
 public:
  RawlogRun(const MapperConfig& config, const MapperArgs& args, MappingResult& result,
            LiveView* live)
      : config_(config),
        args_(args),
        result_(result),
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
    auto tracker = makeTracker(config_);  // validates the ICP sections in every mode
    poses::PoseStage stage = args_.poses.empty()
                                 ? poses::PoseStage(std::move(tracker))
                                 : poses::PoseStage(poses::readPosesFile(args_.poses));
    result_.pose_source = stage.source();
    input::RawlogReaderOptions reader_options;
    reader_options.accept_truncated = args_.accept_truncated;
    input::RawlogReader reader(args_.rawlog, reader_options);
    input::ObservationSource source(reader, input::RoleClassifier(config_.sensors),
                                    args_.selection);
    ProgressLine progress("planar-mapper", !args_.quiet);
    Pacer pacer(args_.playback_rate);
    input::InputStep step;
    for (;;) {
      auto t0 = Clock::now();
      const bool more = source.next(step);
      result_.timing.read_s += since(t0);
      if (!more) {
        break;
      }
      if (!step.observations.empty()) {
        pacer.waitFor(mrpt::Clock::toDouble(step.observations.front().obs->timestamp));
      }
      t0 = Clock::now();
      stage.process(step, args_.rawlog.string());
      const double pose_s = since(t0);
      result_.timing.pose_s += pose_s;
      if (carriesPoses(step)) {
        result_.pose_step_ms.push_back(1000.0 * pose_s);
      }
      t0 = Clock::now();
      collect(step);
      placer_.drain(stage.trajectory(), stage.fixed());
      result_.timing.map_s += since(t0);
      progress.update(reader.compressedPosition(), reader.fileSize(),
                      std::to_string(result_.map.size()) + " points");
    }
    finish(stage, source);
    progress.finish(std::to_string(result_.map.size()) + " points");
    result_.truncation = reader.truncationMessage();
  }

 private:
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
    result_.placement = placer_.stats();
    result_.raw_triangles = mesh_.triangles();
    checkUsable();
    if (online_ && !unorganised_) {
      result_.em_mode = "online";
      result_.timing.em_s = online_->seconds();
      result_.timing.map_s -= online_->seconds();  // the EM's share of the placing time
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
  LiveView* live_;
  std::unique_ptr<OnlineStage> online_;
  bool unorganised_ = false;
  points::RawMeshBuilder mesh_;
  points::ScanPlacer placer_;
  bool seen_any_ = false;
};

MappingResult runCloud(const MapperArgs& args) {
  MappingResult result;
  const auto t0 = Clock::now();
  input::StructureScan scan = input::readPlyCloud(args.cloud);
  result.timing.read_s = since(t0);
  result.pose_source = "cloud";
  result.dropped = scan.dropped;
  result.measurements = scan.measurements();
  if (scan.points.empty()) {
    throw InputError(args.cloud.string() + ": no finite points");
  }
  result.map.addScan(scan, mrpt::math::TPose3D());
  result.placement.placed = 1;
  result.input.structure_scans = 1;
  return result;
}

points::NeighbourGraph graphOf(const MapperConfig& config, const MappingResult& result) {
  return points::neighbourGraph(result.map, config.planar_em.cloud_neighbour_radius_m);
}

void runEm(const MapperConfig& config, const points::NeighbourGraph& graph, MappingResult& result) {
  const auto t0 = Clock::now();
  result.em =
      em::OfflineEm(config.planar_em.em).run(result.map.xyz(), graph.neighbours, graph.rows);
  result.timing.em_s += since(t0);
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
void runRefinement(const MapperConfig& config, const points::NeighbourGraph& graph,
                   MappingResult& result) {
  const auto t0 = Clock::now();
  result.refine =
      refine::refineMap(result.map.xyz(), graph.neighbours, graph.rows, config.planar_em.em,
                        config.refine, result.em->map, sensorOrigins(result.map));
  if (result.refine->fusion.changed_pairs > 0) {
    result.em->message +=
        "; refinement fused " + std::to_string(result.refine->fusion.changed_pairs) + " pairs";
  }
  result.timing.refine_s += since(t0);
}

}  // namespace

MappingResult runPipeline(const MapperConfig& config, const MapperArgs& args, LiveView* live) {
  MappingResult result;
  if (!args.cloud.empty()) {
    result = runCloud(args);
  } else {
    RawlogRun(config, args, result, live).run();
  }
  const bool online_done = result.em_mode == "online";
  std::optional<points::NeighbourGraph> graph;
  if (!args.poses_only && (args.mode == "offline" || (args.mode == "online" && !online_done))) {
    result.em_mode = "offline";  // online falls back for unorganised clouds
    const auto t0 = Clock::now();
    graph = graphOf(config, result);
    result.timing.em_s = since(t0);
    runEm(config, *graph, result);
  } else if (args.mode == "raw" || args.poses_only) {
    result.em_mode = args.poses_only ? "poses-only" : "raw";
  }
  if (result.em && config.refine.enabled && !args.no_refine) {
    const auto t0 = Clock::now();
    if (!graph) {
      graph = graphOf(config, result);
    }
    result.timing.refine_s = since(t0);
    runRefinement(config, *graph, result);
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
