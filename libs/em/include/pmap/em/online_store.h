// The online EM's measurement store: the measurements so far (points, rows,
// neighbour links), their hard assignments with each surface's members and
// exact sufficient statistics, the visit counters and the revisit queue. It
// decides nothing: the E-step (online_em.cpp), the incremental M-step
// (online_mstep.h) and the selection policy (online_selection.h) read and
// change it. Memory and time per scan follow the scan, not the map.
#pragma once

#include <Eigen/Core>
#include <climits>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <unordered_map>
#include <utility>
#include <vector>

#include "pmap/em/neighbours.h"
#include "pmap/em/selection_policy.h"
#include "pmap/em/surface_fit.h"

namespace pmap::em {

/// What the store keeps of a surface: its hard members and their moments.
struct Membership {
  std::vector<std::int32_t> members;
  PlaneMoments moments;             ///< of the hard members, exact
  std::vector<std::int32_t> fresh;  ///< members added since the last M-step
  bool active = false;              ///< members came, went or moved since the last M-step
};

/// Measurements the store has room for before its per-measurement arrays
/// first grow (2^20; 59 MB of address space). Growing a std::vector copies
/// it, and the scan that did it was the slowest of the run (doc/em.md, "No
/// growth spikes"). The room is reserved, not written: a page becomes
/// resident when a measurement is stored in it. Beyond it the arrays double.
constexpr std::size_t kReservedMeasurements = std::size_t{1} << 20;

class OnlineStore {
 public:
  /// `window_scans`: how many recent scans window() lists (>= 1);
  /// `reserved`: room for this many measurements before the first growth.
  explicit OnlineStore(int window_scans, std::size_t reserved = kReservedMeasurements);

  /// Appends one scan's measurements (world frame, finite) with their grid
  /// keys (group = sensor, row = scan rank, col = beam) and links them to
  /// their neighbours in the scan and in the group's previous scan. Returns
  /// the index of the scan's first measurement.
  std::size_t appendScan(const std::vector<Eigen::Vector3d>& points,
                         const std::vector<GridKey>& keys);

  std::size_t size() const { return points_.size(); }
  const std::vector<Eigen::Vector3d>& points() const { return points_; }
  const Eigen::Vector3d& point(std::size_t i) const { return points_[i]; }
  const Neighbours& neighbours() const { return neighbours_; }
  Measurements measurements() const { return {points_, rows_}; }
  /// The recent scans (first measurement, count), oldest first.
  const std::deque<std::pair<std::size_t, std::size_t>>& window() const { return window_; }

  /// Moves measurement i to `p` (finite); its surface's moments follow
  /// exactly, the measurement joins the surface's fresh members (the next
  /// rectangle fit sees it) and the surface is marked active.
  void move(std::size_t i, const Eigen::Vector3d& p);

  // Assignments: the most likely cause of every measurement (-1: outlier).
  std::int32_t best(std::size_t i) const { return best_[i]; }
  const std::vector<std::int32_t>& bests() const { return best_; }
  /// A new, empty surface slot; moments accumulate about `reference`.
  std::int32_t addSurface(const Eigen::Vector3d& reference);
  Membership& surface(std::int32_t j) { return surfaces_[static_cast<std::size_t>(j)]; }
  const Membership& surface(std::int32_t j) const { return surfaces_[static_cast<std::size_t>(j)]; }
  /// Makes j (or -1) the cause of measurement i: members and moments of the
  /// old and the new surface follow, both are marked active.
  void assign(std::size_t i, std::int32_t j);

  // Visits and the revisit queue.
  std::uint8_t visits(std::size_t i) const { return visits_[i]; }
  void resetVisits(std::size_t i) { visits_[i] = 0; }
  bool queued(std::size_t i) const { return queued_[i] != 0; }
  /// Queues i for a revisit unless it is queued already.
  void enqueue(std::size_t i);
  std::size_t queueSize() const { return queue_.size(); }
  /// Takes the oldest queued measurement and counts its visit.
  std::size_t popQueued();

  // Seeding bookkeeping.
  bool notPlanar(std::size_t i) const { return not_planar_[i] != 0; }
  void markNotPlanar(std::size_t i) { not_planar_[i] = 1; }
  std::uint8_t seedTries(std::size_t i) const { return seed_tries_[i]; }
  void countSeedTry(std::size_t i) { ++seed_tries_[i]; }

 private:
  void link(const std::vector<GridKey>& keys, std::size_t first);

  int window_scans_;
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
  std::deque<std::int32_t> queue_;
  std::deque<std::pair<std::size_t, std::size_t>> window_;  ///< recent scans: first, count
  std::vector<Membership> surfaces_;
};

}  // namespace pmap::em
