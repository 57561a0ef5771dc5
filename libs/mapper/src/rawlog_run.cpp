#include "rawlog_run.h"

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/system/datetime.h>

#include <algorithm>
#include <chrono>

#include "pmap/common/error.h"
#include "pmap/common/interrupt.h"
#include "pmap/common/progress.h"
#include "pmap/input/label_inventory.h"
#include "pmap/input/rawlog_reader.h"
#include "pmap/points/raw_mesh.h"
#include "pmap/poses/laser_maps.h"
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
        online_(args.mode == MapMode::kOnline && !args.poses_only
                    ? std::make_unique<OnlineStage>(config.planar_em.em, config.online_em, args.out,
                                                    args.snapshot_every)
                    : nullptr),
        mesh_(config.output.raw_mesh),
        placer_(
            result.points.map, config.sensors.max_pose_gap_s,
            [this](const input::StructureScan& s, std::size_t record) { onPlaced(s, record); }) {}

  void run() {
    checkLabels();
    poses::PoseStage stage = makePoseStage();
    result_.poses.source = args_.poses.empty() ? PoseSource::kIcp : PoseSource::kFile;
    input::RawlogReaderOptions reader_options;
    reader_options.accept_truncated = args_.accept_truncated;
    input::RawlogReader reader(args_.rawlog, reader_options);
    input::ObservationSource source(reader, input::RoleClassifier(config_.sensors),
                                    args_.selection);
    ProgressLine progress("planar-mapper: reading", !args_.quiet);
    Pacer pacer(args_.playback_rate);
    input::InputStep step;
    for (;;) {
      throwIfInterrupted();  // SIGINT / SIGTERM: stop between input steps (staged_outputs.h)
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
      keepLaserScans(stage, step);
      {
        auto in_map = clock_.enter(Stage::kMap);
        if (stage.corrections() != corrections_) {
          followPoses(stage);
        }
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
    result_.input.truncation = reader.truncationMessage();
  }

 private:
  // The pose stage: ICP, or the given poses (checked against the motion
  // limits like odometry).
  poses::PoseStage makePoseStage() const {
    auto tracker = makeIcpTracker(config_);  // validates the ICP sections in every mode
    if (args_.poses.empty()) {
      return poses::PoseStage(std::move(tracker), config_.motion, config_.loops);
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
      result_.poses.step_ms.push_back(1000.0 * since(t0));
    }
  }

  // --gui: each accepted loop closure as a line between its keyframes, at
  // their optimised positions, a little above the floor.
  void showLoops(const poses::PoseStage& stage) {
    const poses::LoopClosingBackEnd* loops = stage.loops();
    if (live_ == nullptr || loops == nullptr) {
      return;
    }
    std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> segments;
    for (const poses::LoopClosure& c : loops->closures()) {
      const poses::Pose2& a = loops->graph().node(c.older);
      const poses::Pose2& b = loops->graph().node(c.newer);
      segments.emplace_back(Eigen::Vector3d(a.x, a.y, 0.1), Eigen::Vector3d(b.x, b.y, 0.1));
    }
    live_->setLoops(std::move(segments));
  }

  // The pose-laser scans the grid and the simple map will hold (laser_maps.h).
  void keepLaserScans(const poses::PoseStage& stage, const input::InputStep& step) {
    if (!args_.poses.empty() || stage.trajectory().empty()) {
      return;
    }
    for (const auto& item : step.observations) {
      if (item.roles.pose_laser) {
        laser_log_.add(mrpt::Clock::toDouble(item.obs->timestamp),
                       stage.trajectory().poses().back().pose,
                       std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(item.obs));
      }
    }
  }

  std::string progressDetail(const poses::PoseStage& stage) const {
    const std::string poses = std::to_string(stage.trajectory().size()) + " poses";
    if (args_.poses_only) {
      return poses;
    }
    return poses + ", " + std::to_string(placer_.stats().placed) + " structure scans, " +
           std::to_string(result_.points.map.size()) + " points";
  }

  void collect(const input::InputStep& step) {
    for (const auto& item : step.observations) {
      const double t = mrpt::Clock::toDouble(item.obs->timestamp);
      InputResult& in = result_.input;
      in.first_time = seen_any_ ? std::min(in.first_time, t) : t;
      in.last_time = seen_any_ ? std::max(in.last_time, t) : t;
      seen_any_ = true;
      if (item.roles.camera && !args_.poses_only && !args_.no_textures) {
        if (auto img = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(item.obs)) {
          result_.input.images.push_back(std::move(img));
        }
      }
      if (item.roles.structure && !args_.poses_only) {
        input::StructureScan scan = input::extractStructureScan(*item.obs, item.structure_index);
        result_.input.dropped += scan.dropped;
        result_.input.measurements += scan.measurements();
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
      mesh_.addScan(result_.points.map, record, scan.rows, scan.cols, scan.organised);
    }
    if (online_ && !offline_fallback_ && scan.organised && scan.rows <= 1) {
      auto in_em = clock_.enter(Stage::kEm);
      online_->addScan(result_.points.map, record);
    } else if (online_ && !offline_fallback_) {
      // The online EM takes its measurements one scan line at a time (the
      // paper's vertical laser); a range image or an unorganised scan has
      // no such order: the whole map goes to the offline EM.
      offline_fallback_ = true;
      result_.mode_note = std::string("scan ") + std::to_string(scan.index) + " (" + scan.label +
                          ") is " + (scan.organised ? "a range image" : "an unorganised cloud") +
                          ": the default (online) mode maps this input with the offline EM, "
                          "which takes whole frames";
    }
    if (live_ != nullptr && live_->due()) {
      const std::optional<em::PlanarMap> planar = online_ && !offline_fallback_
                                                      ? std::optional<em::PlanarMap>(online_->map())
                                                      : std::nullopt;
      live_->update(result_.points.map, record, planar ? &*planar : nullptr);
    }
  }

  void finish(poses::PoseStage& stage, const input::ObservationSource& source) {
    {
      auto in_poses = clock_.enter(Stage::kPoses);
      stage.finish();  // a loop search still on its worker
    }
    result_.input.stats = source.stats();
    result_.poses.stats = stage.stats();
    const auto& in = result_.input.stats;
    const bool no_pose_source = in.pose_scans == 0 && in.odometry == 0 && args_.poses.empty();
    if (no_pose_source && placer_.pending() == 1) {
      result_.poses.source = PoseSource::kIdentity;  // a single 3D frame: its own frame
      placer_.placeAllAt(mrpt::math::TPose3D());
    } else if (no_pose_source && placer_.pending() > 1) {
      throw InputError(args_.rawlog.string() + ": " + std::to_string(placer_.pending()) +
                       " structure scans but no pose source (no odometry, no pose laser; "
                       "give --poses FILE)");
    }
    placer_.drain(stage.trajectory(), true);
    followPoses(stage);  // the map (offline) or its repair (online) uses the final poses
    result_.poses.trajectory = stage.trajectory();
    result_.poses.laser_maps =
        poses::buildLaserMaps(laser_log_, stage.trajectory(), config_.sensors.max_pose_gap_s);
    if (config_.plane_poses.enabled && result_.poses.laser_maps) {
      result_.poses.laser_log = std::move(laser_log_);  // planes may move the poses (pipeline.cpp)
    }
    result_.poses.motion = stage.gate().stats();
    if (const poses::LoopClosingBackEnd* loops = stage.loops()) {
      result_.poses.loops = loops->stats();
      result_.poses.closures = loops->closures();
      if (loops->odometryModel().calibration().edges > 0) {
        result_.poses.odometry_calibration = loops->odometryModel().calibration();
      }
      result_.poses.corrections = stage.corrections();
      result_.poses.front_map_rebuilds = stage.frontMapRebuilds();
      result_.poses.graph = loops->graph();
    }
    const std::string dropped = stage.gate().summary(
        args_.poses.empty() ? "odometry readings or increments" : "given poses");
    if (!dropped.empty()) {
      result_.warnings.push_back(args_.rawlog.string() + ": " + dropped);
    }
    result_.points.placement = placer_.stats();
    result_.points.raw_triangles = mesh_.triangles();
    checkUsable();
    if (online_ && !offline_fallback_) {
      {
        auto in_em = clock_.enter(Stage::kEm);
        online_->finish(result_.points.map);
      }
      result_.sigma_estimate = online_->sigmaEstimate();
      result_.kind = RunKind::kOnline;
      PlanarResult planar;
      planar.online = online_->history();
      planar.repairs = online_->repairs();
      planar.map = online_->map();
      planar.message = "online over " + std::to_string(planar.online.size()) + " scans, " +
                       std::to_string(planar.map.surfaces.size()) + " surfaces";
      result_.planar = std::move(planar);
    }
  }

  // A loop closure rewrote the past trajectory: the scans placed before move
  // with it, and so do their measurements in the online EM (issue 15 item 4).
  void followPoses(const poses::PoseStage& stage) {
    corrections_ = stage.corrections();
    if (corrections_ == 0) {
      return;
    }
    showLoops(stage);
    const std::vector<std::size_t> moved = placer_.follow(stage.trajectory());
    result_.points.scans_moved += moved.size();
    if (online_ && !offline_fallback_ && !moved.empty()) {
      auto in_em = clock_.enter(Stage::kEm);
      online_->moveScans(result_.points.map, moved);
    }
  }

  void checkUsable() const {
    const auto& in = result_.input.stats;
    const std::string file = args_.rawlog.string();
    if (in.pose_scans == 0 && in.structure_scans == 0) {
      throw InputError(file + ": no usable scans (" + std::to_string(in.records) + " records, " +
                       std::to_string(in.observations) +
                       " observations; check the [Sensors] labels and the selection)");
    }
    if (args_.poses_only) {
      if (result_.poses.trajectory.empty()) {
        throw InputError(file + ": no poses computed (no odometry or pose-laser scans)");
      }
      return;
    }
    if (in.structure_scans == 0) {
      throw InputError(file +
                       ": no structure observations (labels in [Sensors] structure); "
                       "use --poses-only to compute poses only");
    }
    if (result_.points.placement.placed == 0) {
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
  bool offline_fallback_ = false;
  std::size_t corrections_ = 0;  ///< the pose stage's corrections() the map follows
  points::RawMeshBuilder mesh_;
  points::ScanPlacer placer_;
  poses::LaserScanLog laser_log_{config_.output.laser_maps};
  bool seen_any_ = false;
};

}  // namespace

void runRawlog(const MapperConfig& config, const MapperArgs& args, StageClock& clock,
               LiveView* live, MappingResult& result) {
  RawlogRun(config, args, result, clock, live).run();
}

}  // namespace pmap::mapper
