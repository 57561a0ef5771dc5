// The mapping pipeline as data flows: rawlog -> input steps -> poses ->
// placed structure points -> raw mesh (-> EM in later stages). Streaming:
// memory grows with the map, not with the file.
#pragma once

#include <mrpt/obs/CObservationImage.h>

#include <array>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "pmap/common/stage_clock.h"
#include "pmap/em/offline_em.h"
#include "pmap/input/observation_source.h"
#include "pmap/input/structure_points.h"
#include "pmap/mapper/live_view.h"
#include "pmap/mapper/mapper_args.h"
#include "pmap/mapper/mapper_config.h"
#include "pmap/mapper/online_stage.h"
#include "pmap/points/point_map.h"
#include "pmap/points/scan_placer.h"
#include "pmap/poses/icp_pose_tracker.h"
#include "pmap/poses/trajectory.h"
#include "pmap/refine/map_refiner.h"

namespace pmap::mapper {

struct MappingResult {
  points::PointMap map;
  poses::Trajectory trajectory;
  std::vector<std::array<std::uint32_t, 3>> raw_triangles;
  std::string pose_source;  ///< "icp", "file", "identity", "cloud"
  input::InputStats input;
  poses::PoseStats pose_stats;
  poses::MotionGateStats motion;  ///< odometry / given poses dropped as implausible
  points::PlacementStats placement;
  input::DropCounts dropped;
  std::uint64_t measurements = 0;  ///< all structure measurements seen (beams, pixels)
  double first_time = 0;           ///< recorded span of the selected observations (s)
  double last_time = 0;
  std::string truncation;          ///< non-empty: accepted truncation message
  std::optional<em::EmResult> em;  ///< the planar map (modes online and offline)
  /// The refinement of em's map (already applied to it).
  std::optional<refine::RefineResult> refine;
  /// Online mode: one record per structure scan fed to the online EM.
  std::vector<OnlineRecord> online;
  /// Wall time of the pose stage for each input step that carried pose
  /// observations (ms).
  std::vector<double> pose_step_ms;
  /// Camera images of the selected records (external images stay on disk;
  /// embedded ones are held in memory), for the textures.
  std::vector<mrpt::obs::CObservationImage::Ptr> images;
  /// What actually ran: online, offline, raw (online falls back to offline
  /// for unorganised clouds, which have no scan order).
  std::string em_mode;
  /// Outcomes worth a warning (printed, and listed in summary.json), e.g.
  /// "nothing found" (doc/robustness.md).
  std::vector<std::string> warnings;
  double duration() const { return last_time > first_time ? last_time - first_time : 0.0; }
};

/// Runs the pipeline on a rawlog or a PLY cloud, timing its stages on
/// `clock` and showing progress in `live` (--gui) when given. Throws
/// ConfigError, InputError (bad data, nothing to map), ProcessingError.
MappingResult runPipeline(const MapperConfig& config, const MapperArgs& args, StageClock& clock,
                          LiveView* live = nullptr);

/// "Nothing found" (doc/robustness.md): a run that read its input correctly
/// but kept no structure point, or found no planar surface, is not an error.
/// It exits 0 with valid, empty outputs; this adds the warning that says so.
void noteNothingFound(const MapperArgs& args, MappingResult& result);

}  // namespace pmap::mapper
