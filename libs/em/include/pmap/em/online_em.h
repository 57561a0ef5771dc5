// The online EM (paper section V): the map is updated after every scan with
// a bounded amount of work, however large the map grows, and past
// assignments are still revised. Three parts:
//  - the measurement store (online_store.h): points, assignments, each
//    surface's members and exact sufficient statistics, visit counters and
//    the revisit queue;
//  - the incremental M-step (online_mstep.h): only active surfaces are
//    refitted, the plane from the statistics, the rectangle from the hull,
//    the newest members and a capped subsample;
//  - the selection policy (online_selection.h): the decisions shared with
//    the offline EM (selection_policy.h) on what one scan can afford.
// This class runs the E-step over a bounded set (the new scan's
// measurements plus at most `revisit_budget` queued past ones, each frozen
// past `freeze_after` visits) and the three parts in turn.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "pmap/em/model_selector.h"
#include "pmap/em/neighbours.h"
#include "pmap/em/offline_em.h"
#include "pmap/em/online_em_options.h"
#include "pmap/em/online_mstep.h"
#include "pmap/em/online_selection.h"
#include "pmap/em/online_store.h"
#include "pmap/em/planar_em_options.h"

namespace pmap::em {

/// What one scan's update (or one movePoints) did.
struct OnlineUpdate {
  int new_points = 0;
  int revisited = 0;   ///< past measurements re-examined
  int reassigned = 0;  ///< most likely causes that changed
  int active_surfaces = 0;
  int moved = 0;  ///< measurements moved (movePoints)
  SelectionChanges changes;
};

/// The online EM's result: its map after the scans so far (it has no
/// termination: every scan's map is a result).
struct OnlineResult {
  PlanarMap map;
  int scans = 0;           ///< scans added
  std::size_t points = 0;  ///< measurements added
  std::string message;     ///< "online over N scans, M surfaces"
};

class OnlineEm {
 public:
  /// Both option structs must validate.
  OnlineEm(const PlanarEmOptions& em, const OnlineEmOptions& online);
  OnlineEm(const OnlineEm&) = delete;  // the parts refer to each other
  OnlineEm& operator=(const OnlineEm&) = delete;

  /// Adds one scan's measurements (world frame, finite) with their grid keys
  /// (group = sensor, row = scan rank, col = beam) and updates the map.
  OnlineUpdate addScan(const std::vector<Eigen::Vector3d>& points,
                       const std::vector<GridKey>& keys);

  /// Moves measurements already added (e.g. after a loop closure corrected
  /// past poses): `indices[k]` (the order of addScan, from 0) goes to
  /// `new_positions[k]` (finite). The sufficient statistics of the surfaces
  /// holding them follow exactly, those surfaces are refitted and examined
  /// for fusion first at the next selection turns, and the moved
  /// measurements are queued for revisiting with a fresh visit count; at
  /// most `revisit_budget` of them are revisited here, the rest by the next
  /// scans. Work: O(moved measurements) for the statistics plus one capped
  /// refit per surface touched. Throws std::invalid_argument when the sizes
  /// differ, an index is out of range or a position is not finite (nothing
  /// is moved then).
  OnlineUpdate movePoints(const std::vector<std::int32_t>& indices,
                          const std::vector<Eigen::Vector3d>& new_positions);

  /// The current map: surfaces, the most likely cause of every measurement
  /// so far, fine triangles over the outliers (computed here, not per scan).
  PlanarMap map() const;
  /// The map with the counts and a one-line summary.
  OnlineResult result() const;

  std::size_t points() const { return store_.size(); }
  int surfaceCount() const { return mstep_.aliveCount(); }
  int scans() const { return scans_; }

 private:
  /// One E-step visit of measurement i.
  void revisit(std::size_t i, OnlineUpdate& u);
  /// Revisits up to `budget` queued measurements, oldest first.
  void revisitQueued(std::size_t budget, OnlineUpdate& u);

  PlanarEmOptions options_;
  OnlineEmOptions online_;
  OnlineStore store_;
  OnlineMStep mstep_;
  OnlineSelection selection_;
  int scans_ = 0;
};

}  // namespace pmap::em
