// The online EM inside the pipeline: every placed structure scan updates the
// map at once (paper section V); the per-scan EM time is measured here, and
// the map can be written every N scans to look at it mid-run.
#pragma once

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "pmap/em/noise_estimate.h"
#include "pmap/em/online_em.h"
#include "pmap/points/grid_keys.h"
#include "pmap/points/point_map.h"

namespace pmap::mapper {

/// One scan's online update, for summary.json and online.csv.
struct OnlineRecord {
  std::int64_t scan = -1;  ///< structure scan index in the file
  double em_ms = 0;        ///< the EM update alone
  int surfaces = 0;
  std::size_t points = 0;  ///< measurements in the map so far
  em::OnlineUpdate update;
};

/// One repair of the online map after a loop closure moved past scans.
struct OnlineRepair {
  std::size_t scans = 0;   ///< scans that moved
  std::size_t points = 0;  ///< measurements moved (OnlineEm::movePoints)
  double ms = 0;           ///< the EM's share of the repair
  em::OnlineUpdate update;
};

class OnlineStage {
 public:
  /// `snapshot_every` > 0 writes OUT_DIR/snapshots/map_NNNNNN.wrl
  /// (products::OutputLayout::snapshotFile) every so many scans; OUT_DIR is
  /// the run's staging folder until the run ends (staged_outputs.h).
  /// With em.sigma_auto the EM starts once em.auto_sigma_points
  /// measurements are placed (or at finish()), with sigma_m estimated from
  /// them (noise_estimate.h); the scans before are fed to it then, in order.
  OnlineStage(const em::PlanarEmOptions& em, const em::OnlineEmOptions& online,
              std::filesystem::path out_dir, int snapshot_every);

  /// Feeds the scan `record` of `map` (just placed). Polls
  /// pmap::throwIfInterrupted() first.
  void addScan(const points::PointMap& map, std::size_t record);

  /// After a loop closure moved the scans `moved` of `map` (already moved
  /// there, ScanPlacer::follow): their measurements move in the EM too, and
  /// the surfaces holding them are refitted (OnlineEm::movePoints; work
  /// O(moved measurements) plus one capped refit per surface touched).
  void moveScans(const points::PointMap& map, const std::vector<std::size_t>& moved);

  /// At the end of the input: an EM still waiting for sigma starts with
  /// what there is.
  void finish(const points::PointMap& map);

  const std::vector<OnlineRecord>& history() const { return history_; }
  const std::vector<OnlineRepair>& repairs() const { return repairs_; }
  double seconds() const { return seconds_; }
  em::PlanarMap map() const { return em_ ? em_->map() : em::PlanarMap{}; }
  /// sigma_m = auto: what was estimated (nullopt: a fixed sigma_m).
  const std::optional<em::NoiseEstimate>& sigmaEstimate() const { return sigma_estimate_; }

 private:
  void writeSnapshot(const points::PointMap& map) const;
  void feed(const points::PointMap& map, std::size_t record);
  void start(const points::PointMap& map);

  em::PlanarEmOptions options_;
  em::OnlineEmOptions online_options_;
  std::optional<em::OnlineEm> em_;
  std::optional<em::NoiseEstimate> sigma_estimate_;
  std::vector<std::size_t> waiting_;  ///< records placed before the EM started
  points::GridKeyer keyer_;
  std::filesystem::path out_dir_;
  int snapshot_every_;
  std::vector<OnlineRecord> history_;
  std::vector<OnlineRepair> repairs_;
  double seconds_ = 0;
};

/// Paces a replay at `rate` times the recorded speed (0: as fast as possible).
class Pacer {
 public:
  explicit Pacer(double rate) : rate_(rate) {}
  /// Waits until the wall time since the first call reaches
  /// (t - first t) / rate.
  void waitFor(double t);

 private:
  double rate_;
  bool started_ = false;
  double t0_ = 0;
  std::chrono::steady_clock::time_point wall0_;
};

}  // namespace pmap::mapper
