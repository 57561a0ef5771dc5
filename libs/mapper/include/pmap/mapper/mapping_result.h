// What a planar-mapper run produced, stage by stage (input -> poses ->
// points -> planar map), and the typed modes the run was made in. The
// strings of the modes exist only at the command line and in summary.json
// (toString / parse*).
#pragma once

#include <mrpt/obs/CObservationImage.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pmap/em/noise_estimate.h"
#include "pmap/em/offline_em.h"
#include "pmap/input/observation_source.h"
#include "pmap/input/structure_points.h"
#include "pmap/mapper/online_stage.h"
#include "pmap/points/point_map.h"
#include "pmap/points/scan_placer.h"
#include "pmap/poses/icp_pose_tracker.h"
#include "pmap/poses/laser_maps.h"
#include "pmap/poses/loop_closure.h"
#include "pmap/poses/motion_gate.h"
#include "pmap/poses/trajectory.h"
#include "pmap/refine/map_refiner.h"
#include "pmap/refine/plane_poses.h"

namespace pmap::mapper {

/// --mode: how the planar map is made.
enum class MapMode {
  kOnline,   ///< updated after every structure scan (the default)
  kOffline,  ///< EM over all measurements at the end
  kRaw,      ///< points and the raw polygon map only
};

/// What the run did: the map mode, or less (--poses-only), or the offline EM
/// where online was asked for an unorganised cloud (no scan order).
enum class RunKind { kOnline, kOffline, kRaw, kPosesOnly };

/// Where the poses came from.
enum class PoseSource {
  kIcp,       ///< MRPT's ICP on odometry and the pose laser
  kFile,      ///< --poses
  kIdentity,  ///< a single 3D frame: its own frame is the world
  kCloud,     ///< --cloud: the cloud's frame
};

const char* toString(MapMode mode);
const char* toString(RunKind kind);
const char* toString(PoseSource source);
/// "online", "offline", "raw"; nullopt otherwise.
std::optional<MapMode> parseMapMode(const std::string& text);

/// What was read.
struct InputResult {
  input::InputStats stats;
  input::DropCounts dropped;
  std::uint64_t measurements = 0;  ///< all structure measurements seen (beams, pixels)
  double first_time = 0;           ///< recorded span of the selected observations (s)
  double last_time = 0;
  std::string truncation;  ///< non-empty: accepted truncation message
  /// Camera images of the selected records (external images stay on disk;
  /// embedded ones are held in memory), for the textures.
  std::vector<mrpt::obs::CObservationImage::Ptr> images;
  double duration() const { return last_time > first_time ? last_time - first_time : 0.0; }
};

/// The poses.
struct PoseResult {
  PoseSource source = PoseSource::kIcp;
  poses::Trajectory trajectory;
  poses::PoseStats stats;
  poses::MotionGateStats motion;                 ///< odometry / given poses dropped as implausible
  std::optional<poses::LoopClosureStats> loops;  ///< with [Poses] loop_closure = true
  std::vector<poses::LoopClosure> closures;      ///< the accepted loop closures, in order
  std::size_t corrections = 0;                   ///< loop closures that rewrote the past trajectory
  std::size_t front_map_rebuilds = 0;            ///< the ICP front end's map rebuilt from the graph
  std::optional<poses::PoseGraph> graph;         ///< the optimised pose graph (loop closure)
  /// The wheel odometry's calibration (loop closure with calibrated odometry).
  std::optional<poses::OdometryCalibration> odometry_calibration;
  /// The pose laser's grid and simple map from the final poses ([Output]
  /// laser_maps; absent with --poses FILE or without pose-laser scans).
  std::optional<poses::LaserMaps> laser_maps;
  /// The pose-laser scans they were built from, kept only when a later stage
  /// moves the poses ([Poses] plane_refinement) and rebuilds them.
  std::optional<poses::LaserScanLog> laser_log;
  /// Planes correct poses ([Poses] plane_refinement, offline mode): one
  /// record per round, the trajectory and the points moved by each.
  std::vector<refine::PlanePoseResult> plane_rounds;
  /// Wall time of the pose stage for each input step that carried a
  /// pose-laser scan (ms).
  std::vector<double> step_ms;
};

/// The placed structure points and the raw polygon map.
struct PointsResult {
  points::PointMap map;
  points::PlacementStats placement;
  std::vector<std::array<std::uint32_t, 3>> raw_triangles;
  /// Scan moves after loop closures rewrote the past trajectory
  /// (ScanPlacer::follow; a scan moved twice counts twice).
  std::size_t scans_moved = 0;
};

/// How the offline EM ended (absent for the online EM, which has no end).
struct OfflineRun {
  em::Termination termination = em::Termination::kNoPoints;
  int iterations = 0;
  std::vector<em::IterationRecord> history;
  int blocks = 0;  ///< spatial blocks (em::EmResult)
  int blocks_unconverged = 0;
};

/// The planar map and how it was made.
struct PlanarResult {
  em::PlanarMap map;  ///< after the refinement, when it ran
  std::string message;
  std::optional<OfflineRun> offline;           ///< the offline EM's run
  std::vector<OnlineRecord> online;            ///< the online EM: one record per structure scan
  std::vector<OnlineRepair> repairs;           ///< the online map's repairs after loop closures
  std::optional<refine::RefineResult> refine;  ///< the refinement (applied to `map`)
};

struct MappingResult {
  RunKind kind = RunKind::kOnline;
  InputResult input;
  PoseResult poses;
  PointsResult points;
  std::optional<PlanarResult> planar;  ///< kinds online and offline
  /// `sigma_m = auto`: the estimate the EM and the refinement used.
  std::optional<em::NoiseEstimate> sigma_estimate;
  /// Why the default (online) mode ran the offline EM instead (empty: it
  /// did not): summary.json "mode_note".
  std::string mode_note;
  /// Outcomes worth a warning (printed, and listed in summary.json), e.g.
  /// "nothing found" (doc/robustness.md).
  std::vector<std::string> warnings;
};

}  // namespace pmap::mapper
