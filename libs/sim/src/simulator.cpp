#include "pmap/sim/simulator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <utility>

#include "pmap/common/error.h"
#include "pmap/common/interrupt.h"
#include "pmap/common/output_set.h"
#include "pmap/common/progress.h"
#include "pmap/sim/camera_rig.h"
#include "pmap/sim/ground_truth.h"
#include "pmap/sim/laser_sim.h"
#include "pmap/sim/observation_factory.h"
#include "pmap/sim/odometry_sim.h"
#include "pmap/sim/path_check.h"
#include "pmap/sim/voxel_path_check.h"
#include "pmap/sim/world_builder.h"
#include "pmap/sim/world_loader.h"

namespace pmap::sim {
namespace {

/// One scan of a laser from a robot pose at a time (where the people are), by
/// the world's own ray casting.
using Scanner = std::function<SimulatedScan(const Pose2D&, const LaserOptions&, const NoiseOptions&,
                                            Rng&, double t_s)>;

/// Simulates the cycles of one run and feeds the rawlog and the ground truth.
/// Without `beam_ids` (voxel worlds) the structure scans carry no hit ids.
class CycleRunner {
 public:
  CycleRunner(const World& world, const Trajectory& trajectory, Scanner scanner, bool beam_ids,
              const SimulatorOptions& options, const CameraRig* rig)
      : world_(world),
        trajectory_(trajectory),
        scanner_(std::move(scanner)),
        beam_ids_(beam_ids),
        options_(options),
        rig_(rig),
        odometry_(world.noise, options.seed) {}

  CycleRecord run(std::size_t k, GroundTruthRecorder& gt);
  std::size_t images() const { return images_; }
  const OdometrySimulator& odometry() const { return odometry_; }

 private:
  using Timed = std::pair<double, mrpt::obs::CObservation::Ptr>;
  Timed scan(const LaserOptions& laser, std::size_t k, double t_rel, GroundTruthRecorder* gt);

  const World& world_;
  const Trajectory& trajectory_;
  Scanner scanner_;
  bool beam_ids_;
  const SimulatorOptions& options_;
  const CameraRig* rig_;
  OdometrySimulator odometry_;
  Pose2D previous_pose_;
  int next_image_ = 0;
  std::size_t images_ = 0;
};

CycleRunner::Timed CycleRunner::scan(const LaserOptions& laser, std::size_t k, double t_rel,
                                     GroundTruthRecorder* gt) {
  const double sigma = world_.noise.range_sigma_m;
  Rng rng(deriveSeed(options_.seed, "laser:" + laser.label, k));
  const SimulatedScan s = scanner_(trajectory_.poseAtTime(t_rel), laser, world_.noise, rng, t_rel);
  const auto stamp = simTimestamp(world_.sensors.start_time_s, t_rel);
  if (gt != nullptr) {
    gt->addStructureScan(mrpt::Clock::toDouble(stamp), laser.label,
                         beam_ids_ ? s.hit_ids : std::vector<int>{});
  }
  return {t_rel, makeScanObservation(laser, s, stamp, sigma)};
}

CycleRecord CycleRunner::run(std::size_t k, GroundTruthRecorder& gt) {
  const SensorOptions& sensors = world_.sensors;
  const double t_k = static_cast<double>(k) / sensors.cycle_hz;
  const Pose2D pose = trajectory_.poseAtTime(t_k);
  const Pose2D increment = k == 0 ? Pose2D{} : odometry_.advance(between(previous_pose_, pose));
  previous_pose_ = pose;
  const auto stamp = simTimestamp(sensors.start_time_s, t_k);
  CycleRecord record;
  record.odometry = makeOdometryObservation(sensors.odometry_label, odometry_.pose(), stamp);
  record.action = makeOdometryAction(increment, stamp);

  std::vector<Timed> timed;
  timed.push_back(scan(sensors.laser_h, k, t_k + sensors.laser_h.time_offset_s, nullptr));
  const bool image_due = rig_ != nullptr && next_image_ / sensors.cameras.rate_hz <= t_k + 1e-9;
  if (image_due) {
    const double t_cam = t_k + sensors.cameras.time_offset_s;
    const Capture capture = rig_->capture(trajectory_.poseAtTime(t_cam), next_image_,
                                          simTimestamp(sensors.start_time_s, t_cam));
    for (std::size_t i = 0; i < capture.observations.size(); ++i) {
      timed.emplace_back(t_cam, capture.observations[i]);
      gt.addImage(capture.records[i]);
      ++images_;
    }
    while (next_image_ / sensors.cameras.rate_hz <= t_k + 1e-9) {
      ++next_image_;
    }
  }
  timed.push_back(scan(sensors.laser_v, k, t_k + sensors.laser_v.time_offset_s, &gt));
  std::stable_sort(timed.begin(), timed.end(),
                   [](const Timed& a, const Timed& b) { return a.first < b.first; });

  std::vector<double> pose_times = {t_k};
  for (const Timed& t : timed) {
    pose_times.push_back(t.first);
    record.observations.push_back(t.second);
  }
  std::sort(pose_times.begin(), pose_times.end());
  for (const double t : pose_times) {
    gt.addPose(mrpt::Clock::toDouble(simTimestamp(sensors.start_time_s, t)),
               trajectory_.poseAtTime(t));
  }
  return record;
}

/// The scans of a voxel world (`voxel_caster` set) or of a world of rectangles;
/// the world's people walk through either.
Scanner makeScanner(const World& world, const RayCaster* rectangles,
                    const VoxelRayCaster* voxel_caster) {
  if (voxel_caster != nullptr) {
    const VoxelRayCaster& voxels = *voxel_caster;
    return [&voxels, &world](const Pose2D& robot, const LaserOptions& laser,
                             const NoiseOptions& noise, Rng& rng, double t_s) {
      const PeopleAt people(world.people, t_s);
      const BeamCaster cast = [&](const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                                  double max_range_m) -> std::optional<BeamHit> {
        const std::optional<VoxelHit> hit = voxels.cast(origin, dir, max_range_m);
        const double t_max = hit ? hit->t : max_range_m;
        if (const auto p = people.cast(origin, dir, 1e-9, t_max)) {
          return BeamHit{p->hit.t, p->id, p->hit.normal};
        }
        return hit ? std::optional<BeamHit>(BeamHit{hit->t, -1}) : std::nullopt;
      };
      return simulateScan(cast, robot, laser, noise, rng);
    };
  }
  const RayCaster& caster = *rectangles;
  return
      [&caster](const Pose2D& robot, const LaserOptions& laser, const NoiseOptions& noise, Rng& rng,
                double t_s) { return simulateScan(caster, robot, laser, noise, rng, t_s); };
}

/// People walk where the robot cannot be: refused with the time and place
/// where one of them comes within the robot's radius of the robot.
void checkPeopleMissTheRobot(const World& world, const Trajectory& robot, double duration_s,
                             const std::string& file) {
  constexpr double kStep_s = 0.02;
  for (const WalkingPerson& p : world.people) {
    const double reach = world.path.robot_radius_m + p.spec().radius_m;
    for (double t = 0.0; t <= duration_s; t += kStep_s) {
      const Pose2D r = robot.poseAtTime(t);
      const VerticalCylinder c = p.at(t);
      if ((c.centre - Eigen::Vector2d(r.x, r.y)).norm() < reach) {
        char at[96];
        std::snprintf(at, sizeof(at), " at t = %.2f s near (%.2f, %.2f)", t, r.x, r.y);
        throw ConfigError(file + ": " + p.spec().where + ": the person walks into the robot" + at);
      }
    }
  }
}

GroundTruthMeta makeMeta(const World& world, const SimulatorOptions& options,
                         const Trajectory& trajectory, const CycleRunner& runner,
                         const OutputPaths& paths, std::size_t cycles, const VoxelWorld* voxels) {
  const SensorOptions& sensors = world.sensors;
  GroundTruthMeta meta;
  meta.world_name = world.name;
  meta.world_file = options.world_file.filename().string();
  if (voxels != nullptr) {
    meta.octomap = octomapJson(*voxels);
  }
  meta.seed = options.seed;
  meta.sigma_m = world.noise.range_sigma_m;
  meta.rawlog_format = rawlogFormatName(options.format);
  meta.start_time_s = sensors.start_time_s;
  meta.images_dir_name = paths.images_dir_name;
  meta.cameras_enabled = sensors.cameras.enabled;
  meta.intrinsics = PinholeIntrinsics::fromFov(sensors.cameras.width_px, sensors.cameras.height_px,
                                               degToRad(sensors.cameras.hfov_deg));
  meta.intrinsics.distortion = sensors.cameras.lens.distortion;
  meta.odometry = {runner.odometry().scaleError(), runner.odometry().headingDriftRadPerM()};
  meta.path_length_m = trajectory.length_m();
  meta.duration_s = static_cast<double>(cycles - 1) / sensors.cycle_hz;
  meta.cycles = cycles;
  meta.images = runner.images();
  return meta;
}

}  // namespace

bool SimulatorOptions::validate(std::string* why) const {
  auto fail = [why](const std::string& m) {
    if (why != nullptr) {
      *why = m;
    }
    return false;
  };
  if (world_file.empty()) {
    return fail("world_file must be set");
  }
  if (out_prefix.empty()) {
    return fail("out_prefix must be set");
  }
  if (sigma_m && !(*sigma_m >= 0.0 && *sigma_m <= 1.0)) {
    return fail("sigma_m must be in [0, 1] metres");
  }
  if (duration_s && !(*duration_s > 0.0 && *duration_s <= 1.0e6)) {
    return fail("duration_s must be in (0, 1e6] seconds");
  }
  return true;
}

Simulator::Simulator(SimulatorOptions options) : options_(std::move(options)) {
  std::string why;
  if (!options_.validate(&why)) {
    throw ConfigError("simulator options: " + why);
  }
  world_ = buildWorld(loadWorldFile(options_.world_file));
  if (options_.sigma_m) {
    world_.noise.range_sigma_m = *options_.sigma_m;
  }
  if (!options_.cameras) {
    world_.sensors.cameras.enabled = false;
  }
  trajectory_ = std::make_unique<Trajectory>(world_.path, world_.source_file);
  // Over the part of the path this run drives (--duration may end it early).
  checkPeopleMissTheRobot(
      world_, *trajectory_,
      std::min(trajectory_->duration_s(), options_.duration_s.value_or(trajectory_->duration_s())),
      world_.source_file);
  if (world_.octomap) {
    voxels_ = std::make_unique<VoxelWorld>(loadVoxelWorld(*world_.octomap));
    voxel_caster_ = std::make_unique<VoxelRayCaster>(*voxels_);
    checkVoxelPathClearance(*voxels_, *trajectory_, world_.path.robot_radius_m, world_.sensors,
                            world_.source_file);
    return;
  }
  caster_ = std::make_unique<RayCaster>(world_);
  checkPathClearance(*caster_, *trajectory_, world_.path.robot_radius_m, world_.source_file);
  for (const WalkingPerson& p : world_.people) {
    checkPathClearance(*caster_, p.walk(), p.spec().radius_m,
                       world_.source_file + ": " + p.spec().where, "the person", "walks");
  }
}

Simulator::~Simulator() = default;

std::size_t Simulator::cycleCount() const {
  const SensorOptions& s = world_.sensors;
  double total = trajectory_->duration_s();
  if (options_.duration_s) {
    total = std::min(total, *options_.duration_s);
  }
  double last_offset = std::max(s.laser_h.time_offset_s, s.laser_v.time_offset_s);
  if (s.cameras.enabled) {
    last_offset = std::max(last_offset, s.cameras.time_offset_s);
  }
  const double cycles = std::floor((total - last_offset) * s.cycle_hz + 1e-9) + 1.0;
  return static_cast<std::size_t>(std::max(1.0, cycles));
}

SimulationSummary Simulator::run() {
  SimulationSummary summary;
  summary.paths = OutputPaths::fromPrefix(options_.out_prefix);
  OutputSet outputs;  // removes every temporary if anything below throws
  const OutputPaths staged = summary.paths.stageIn(outputs);
  throwIfInterrupted();
  const std::vector<cv::Mat> posters = writePosterImages(world_, options_.seed, staged.images_dir);
  std::unique_ptr<CameraRig> rig;
  if (world_.sensors.cameras.enabled) {
    rig = std::make_unique<CameraRig>(world_, posters, options_.seed, staged.images_dir);
  }
  RawlogWriter writer(staged.rawlog, options_.format);
  GroundTruthRecorder gt;
  CycleRunner runner(world_, *trajectory_, makeScanner(world_, caster_.get(), voxel_caster_.get()),
                     voxels_ == nullptr, options_, rig.get());
  const std::size_t n = cycleCount();
  ProgressLine progress("indoor-sim", options_.progress);
  for (std::size_t k = 0; k < n; ++k) {
    throwIfInterrupted();
    writer.write(runner.run(k, gt));
    progress.update(k + 1, n, std::to_string(runner.images()) + " images");
  }
  progress.finish(std::to_string(n) + " cycles, " + std::to_string(runner.images()) + " images");

  const GroundTruthMeta meta =
      makeMeta(world_, options_, *trajectory_, runner, staged, n, voxels_.get());
  writer.finish();
  gt.write(staged.gt_json, staged.poses_txt, world_, meta);
  throwIfInterrupted();  // the last chance: from here on the run completes
  outputs.commit();

  summary.cycles = n;
  summary.structure_scans = gt.structureScanCount();
  summary.images = runner.images();
  summary.rawlog_objects = writer.objectsWritten();
  summary.surfaces = world_.surfaces.size();
  summary.occupied_voxels = voxels_ ? voxels_->occupiedVoxels() : 0;
  summary.duration_s = meta.duration_s;
  summary.path_length_m = trajectory_->length_m();
  return summary;
}

}  // namespace pmap::sim
