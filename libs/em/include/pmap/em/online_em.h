// The online EM (paper section V): the map is updated after every scan with
// a bounded amount of work, however large the map grows, and past
// assignments are still revised.
//  - E-step over a bounded set: the new scan's measurements plus at most
//    `revisit_budget` past ones that lie on the boundary of two surfaces or are
//    unexplained; each measurement counts its visits and is frozen past
//    `freeze_after`.
//  - M-step only for active surfaces (a most likely assignment moved to or
//    from them), from hard assignments: the plane from sufficient statistics
//    kept incrementally (exact for hard assignments), the rectangle from the
//    surface's hull, its newest points and a seeded random subsample capped at
//    `sample_cap`.
//  - Model selection every scan: unexplained measurements of the last
//    `seed_window_scans` scans seed surfaces; surfaces still below
//    min_support after `removal_after_scans` scans, or curved, are removed;
//    and, beyond the paper's brief window, every surface keeps being tested
//    for fusion, residual splits and coverage cuts (round robin,
//    `selection_per_scan` surfaces per scan, on a capped subsample).
#pragma once

#include <Eigen/Core>
#include <climits>
#include <cstdint>
#include <deque>
#include <random>
#include <unordered_map>
#include <vector>

#include "pmap/em/incremental_index.h"
#include "pmap/em/measurement_model.h"
#include "pmap/em/neighbours.h"
#include "pmap/em/offline_em.h"
#include "pmap/em/online_em_options.h"
#include "pmap/em/planar_em_options.h"
#include "pmap/em/surface_fit.h"

namespace pmap::em {

/// What one scan's update did.
struct OnlineUpdate {
  int new_points = 0;
  int revisited = 0;   ///< past measurements re-examined
  int reassigned = 0;  ///< most likely causes that changed
  int active_surfaces = 0;
  SelectionChanges changes;
};

class OnlineEm {
 public:
  OnlineEm(const PlanarEmOptions& em, const OnlineEmOptions& online);

  /// Adds one scan's measurements (world frame, finite) with their grid keys
  /// (group = sensor, row = scan rank, col = beam) and updates the map.
  OnlineUpdate addScan(const std::vector<Eigen::Vector3d>& points,
                       const std::vector<GridKey>& keys);

  /// The current map: surfaces, the most likely cause of every measurement
  /// so far, fine triangles over the outliers (computed here, not per scan).
  PlanarMap map() const;

  std::size_t points() const { return points_.size(); }
  int surfaceCount() const;

 private:
  struct OnlineSurface {
    Rectangle rect;
    std::int32_t id = -1;
    PlaneMoments moments;  ///< hard members, exact
    std::vector<std::int32_t> members;
    std::vector<std::int32_t> hull;   ///< members on the last rectangle's hull
    std::vector<std::int32_t> fresh;  ///< members added since the last M-step
    int created_scan = 0;
    bool alive = true;
    bool active = false;
    bool trimmed = false;
    bool poorly_covered = false;  ///< the last M-step left most of the rectangle empty
  };
  struct Cause {
    std::int32_t best = -1;
    double best_score = 0;
    double margin = 0;  ///< best minus second-best score (nats)
  };

  // Bookkeeping (online_em.cpp).
  void appendScan(const std::vector<Eigen::Vector3d>& points, const std::vector<GridKey>& keys);
  Cause evaluate(std::size_t i) const;
  std::int32_t continuation(std::size_t i) const;
  bool poorCoverage(const std::vector<std::int32_t>& basis, const Rectangle& rect) const;
  void assign(std::size_t i, std::int32_t surface);
  void revisit(std::size_t i, OnlineUpdate& u);
  void maximize(std::int32_t j);
  std::vector<std::int32_t> sampleMembers(const OnlineSurface& s, int cap);
  std::int32_t createSurface(const Rectangle& rect, const std::vector<std::int32_t>& members);
  void removeSurface(std::int32_t j);

  // Model selection (online_selection.cpp).
  int seedNew();
  int removeUnsupported();
  void selectRoundRobin(SelectionChanges& c);
  bool tryFuse(std::int32_t j);
  struct SplitSample {
    std::vector<std::int32_t> points;  ///< a capped subsample and the hull
    std::vector<double> loss;          ///< per point: worse without the surface (nats, scaled)
    double scale = 1;                  ///< members per sampled point
    double cell = 0;                   ///< grid cell of the split tests (m)
    std::size_t min_part = 0;          ///< smallest part, in sampled points
  };
  SplitSample splitSample(std::int32_t j);
  std::vector<std::vector<std::vector<std::int32_t>>> splitOptions(std::int32_t j,
                                                                   const SplitSample& x) const;
  double splitGain(std::int32_t j, const SplitSample& x,
                   const std::vector<std::vector<std::int32_t>>& parts,
                   const std::vector<Rectangle>& rects) const;
  bool trySplit(std::int32_t j);
  bool tryRecut(std::int32_t j, std::int32_t k);
  bool leavesUnexplained(std::int32_t j, const Rectangle& kept) const;
  bool validSurface(const std::vector<std::int32_t>& members, const Rectangle& rect) const;
  double hardScore(std::size_t i) const;

  PlanarEmOptions options_;
  OnlineEmOptions online_;
  MeasurementModel model_;
  double cutoff_;
  IncrementalIndex index_;
  std::mt19937_64 rng_;

  std::vector<Eigen::Vector3d> points_;
  std::vector<std::int32_t> rows_;
  Neighbours neighbours_;
  struct RowIndex {
    std::int32_t row = INT32_MIN;
    std::unordered_map<std::int32_t, std::int32_t> cols;  ///< col -> point
  };
  std::unordered_map<std::int32_t, RowIndex> last_row_;  ///< per group: its newest row
  std::vector<std::int32_t> best_;
  std::vector<std::int32_t> member_pos_;  ///< position in its surface's member list
  std::vector<std::uint8_t> visits_;
  std::vector<char> queued_;
  std::vector<char> not_planar_;
  std::vector<std::uint8_t> seed_tries_;  ///< seeding turns a point stayed unexplained
  static constexpr std::uint8_t kSeedTries = 4;
  static constexpr std::size_t kSeedAttempts = 6;  ///< regions grown per seeding turn
  std::deque<std::int32_t> queue_;
  std::deque<std::pair<std::size_t, std::size_t>> window_;  ///< recent scans: first, count

  std::vector<OnlineSurface> surfaces_;
  std::int32_t next_id_ = 0;
  std::size_t cursor_ = 0;  ///< round robin over surfaces
  bool fuse_turn_ = true;   ///< selection turns alternate fusion and split tests
  int scans_ = 0;
};

}  // namespace pmap::em
