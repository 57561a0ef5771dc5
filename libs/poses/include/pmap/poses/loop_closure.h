// The pose graph back end behind the ICP front end (doc/poses.md, "Loop
// closure"): keyframes every keyframe_distance_m / keyframe_angle_deg of
// front-end motion, each linked to the previous one by the front end's
// relative pose (whose standard deviations grow with the distance moved and
// the turn: odometry_sigma_fraction, odometry_sigma_deg), refined
// point-to-line against the recent keyframes with that as its prior, its
// information from the match (refine_keyframes, scan_refiner.h), and loop
// edges to older keyframes found by scan-to-submap matching (loop_search.h).
//
// At each new keyframe, older keyframes (at least min_loop_path_m of path
// behind) whose estimated position lies inside a search window are
// candidates; the window grows with the path travelled since the last
// closure (the accumulated uncertainty): radius = min(max_search_radius_m,
// search_radius_m + search_growth * path), angles likewise. The best
// candidates (at most candidates_per_keyframe, spread along the path) are
// verified by a correlative scan-to-submap match that needs no good initial
// guess (scan_matcher.h); a match is accepted when its score passes, when
// it is unique (not on the search window's edge, no other pose of the window
// at least ambiguity_distance_m away scoring max_ambiguity of it: corridors
// alias along their axis), when the beams' free space agrees, and when the
// graph can agree with it: solved with the loop, the graph's objective must
// not rise by more than max_chi2 / 2 (the innovation test; a loop that the
// rest of the graph cannot agree with is refused). Once kept, a loop edge is
// under a Cauchy loss. The work per keyframe is bounded by the candidate
// count and the window's size. With search_latency_keyframes > 0 the search
// and the test both run on a worker thread, on copies.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <deque>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pmap/common/serial_worker.h"
#include "pmap/poses/free_space.h"
#include "pmap/poses/keyframe.h"
#include "pmap/poses/loop_closure_options.h"
#include "pmap/poses/loop_search.h"
#include "pmap/poses/odometry_model.h"
#include "pmap/poses/path_constraints.h"
#include "pmap/poses/pose_graph.h"
#include "pmap/poses/scan_matcher.h"
#include "pmap/poses/scan_refiner.h"

namespace pmap::poses {

/// Where the scans after a keyframe are placed: the last refined scan (or
/// the keyframe itself), by its front-end pose and its refined pose in the
/// keyframe's frame; a later front-end pose follows it with the front end's
/// motion since.
struct ScanAnchor {
  std::size_t scan = 0;  ///< the back end's count of scans when this anchor was set
  std::size_t keyframe = 0;
  Pose2 front;        ///< the anchor's front-end pose
  Pose2 in_keyframe;  ///< the anchor's pose in the keyframe's frame
};

/// One accepted loop closure.
struct LoopClosure {
  std::size_t older = 0;  ///< keyframe indices
  std::size_t newer = 0;
  double older_t = 0;  ///< time of the older keyframe (s)
  double t = 0;        ///< time of the newer keyframe (s)
  Pose2 measurement;   ///< the newer keyframe's pose in the older one's frame (the match)
  double score = 0;
  double moved_m = 0;   ///< how far the newer keyframe moved when the graph was solved
  double solve_ms = 0;  ///< that solve's wall time
  /// The direction (older's frame) the loop left free: a match ambiguous
  /// along a corridor's axis (accept_axis_ambiguity); zero for none.
  Eigen::Vector2d free_axis = Eigen::Vector2d::Zero();
};

struct LoopClosureStats {
  std::size_t keyframes = 0;
  std::size_t odometry_keyframes = 0;   ///< made on the wheels' distance (front end stalled)
  std::size_t refined_edges = 0;        ///< keyframe edges refined point-to-line
  std::size_t refined_scans = 0;        ///< scans between keyframes refined the same way
  std::size_t candidates = 0;           ///< verified by a scan-to-submap match
  std::size_t rejected_match = 0;       ///< no pose of the window scored min_score
  std::size_t rejected_ambiguous = 0;   ///< another pose of the window scored nearly as well
  std::size_t rejected_free_space = 0;  ///< the best pose contradicts the beams' free space
  std::size_t axis_only = 0;            ///< verified, ambiguous along one line only
  std::size_t rejected_chi2 = 0;        ///< refused by the innovation test
  std::size_t accepted = 0;
  std::size_t path_constraints = 0;           ///< keyframe-to-submap edges in the last solve
  std::size_t path_constraints_rejected = 0;  ///< matches the graph disagreed with
  double search_s = 0;  ///< wall time of candidate search and matching (worker thread or not)
  double solve_s = 0;   ///< wall time of the loops' graph solves (worker thread or not)
  double wait_s = 0;    ///< time the front end waited for a worker's job (search and test)
};

/// A loop's test (LoopClosingBackEnd, "Which loops are kept"): a copy of
/// the graph solved with the loop under a plain quadratic cost.
struct LoopTest {
  double innovation = 0;     ///< 2 (F_after - F_before)
  std::vector<Pose2> nodes;  ///< the copy's nodes after the solve
  double solve_s = 0;        ///< the solve's wall time
  /// Whether the loop is kept: its innovation at most max_chi2 (NaN: no).
  bool keeps(double max_chi2) const { return innovation <= max_chi2; }
};

/// `graph` solved with `edge` added (not under the robust loss).
LoopTest testLoop(PoseGraph graph, const PoseEdge& edge);

/// `graph` with a kept loop: the edge under the robust loss, the nodes
/// where its test's solve put them (`nodes`, the first of the graph's) and
/// the keyframes added since then moved along their keyframe edges, as a
/// solve of the whole graph would have left them: they are the chain's
/// dangling end (no loop reaches them, only keyframe edges join them), whose
/// residuals are zero at the optimum.
void keepLoop(PoseGraph& graph, const PoseEdge& edge, const std::vector<Pose2>& nodes);

/// A keyframe's search and, when it found a loop, that loop's test on the
/// graph as the back end will have it when the outcome is applied.
struct LoopOutcome {
  LoopSearchResult search;
  std::optional<LoopTest> test;
};

/// The loops kept by the worker's jobs, so that a later job can test its
/// loop on the graph with them although the front end had not applied them
/// yet when the job was prepared. Touched only by the jobs, which run one
/// at a time.
struct KeptLoops {
  struct Loop {
    std::size_t job = 0;
    PoseEdge edge;
    std::vector<Pose2> nodes;
  };
  std::deque<Loop> loops;
};

class LoopClosingBackEnd {
 public:
  explicit LoopClosingBackEnd(LoopClosureOptions options, ScanMatchOptions match = {});

  /// The front end's pose of a pose-laser scan at `t`, the scan's points
  /// (robot frame) and the wheel odometry at the scan (none: the log has
  /// none). Returns true when a loop closure moved the graph.
  bool addScan(double t, const Pose2& front, std::vector<Eigen::Vector2d> points,
               const std::optional<OdometrySample>& odometry = std::nullopt);
  /// At the end of the input: applies the searches still pending, in
  /// order. Returns true when one of their loop closures moved the graph.
  bool finish();

  /// The world pose of a front-end pose taken after `anchor` (the default
  /// anchor, scan 0, stands for "before the first keyframe"); only
  /// meaningful once there is a keyframe.
  Pose2 corrected(const ScanAnchor& anchor, const Pose2& front) const;
  /// The newest anchor (the newest keyframe or a scan refined after it).
  const ScanAnchor& anchor() const { return anchor_; }
  /// The newest keyframe's index; only meaningful once there is one.
  std::size_t newest() const { return keyframes_.size() - 1; }
  bool empty() const { return keyframes_.empty(); }

  const std::vector<Keyframe>& keyframes() const { return keyframes_; }
  const PoseGraph& graph() const { return graph_; }
  /// The points of the keyframes whose optimised pose lies within
  /// `radius_m` of `centre` (graph frame), in the frame `frame` (the world
  /// seen from it), each scan thinned to points at least `spacing_m` apart
  /// along it: the front end's local map (loop_closing_stage.h).
  std::vector<Eigen::Vector2d> localMap(const Pose2& centre, double radius_m, const Pose2& frame,
                                        double spacing_m) const;
  const std::vector<LoopClosure>& closures() const { return closures_; }
  const LoopClosureStats& stats() const { return stats_; }
  /// The odometry's calibration so far (odometry_model.h).
  const OdometryModel& odometryModel() const { return odometry_model_; }
  const LoopClosureOptions& options() const { return options_; }

 private:
  bool isKeyframe(const Pose2& front, const std::optional<OdometrySample>& odometry);
  void addKeyframe(double t, const Pose2& front, std::vector<Eigen::Vector2d> points,
                   const std::optional<OdometrySample>& odometry);
  Eigen::Matrix3d odometryInformation(const Pose2& from, const Pose2& to) const;
  bool usesOdometry(const Keyframe& from, const std::optional<OdometrySample>& odometry) const;
  MotionPrior motionPrior(const Keyframe& from, const Pose2& front,
                          const std::optional<OdometrySample>& odometry) const;
  bool refineEdge(const Keyframe& from, const Keyframe& to, PoseEdge& edge);
  void refineScan(const std::vector<Eigen::Vector2d>& points, const Pose2& front,
                  const std::optional<OdometrySample>& odometry);
  const LineMap& recentMap();
  bool closeLoop();
  std::vector<std::size_t> candidates(double radius) const;
  std::vector<Rays> scansAround(std::size_t centre, double half_path_m, bool optimised,
                                bool only_older) const;
  LoopSearch prepareSearch() const;
  std::function<LoopOutcome()> prepareJob();
  bool apply(const LoopOutcome& outcome);
  bool applyOldest();
  bool finalSolve();

  LoopClosureOptions options_;
  ScanMatchOptions match_options_;
  std::vector<Keyframe> keyframes_;
  PoseGraph graph_;
  std::vector<LoopClosure> closures_;
  LoopClosureStats stats_;
  double path_m_ = 0;
  Pose2 last_front_;
  bool have_front_ = false;
  double path_at_last_closure_ = 0;
  /// Searches queued on the worker (search_latency_keyframes > 0), oldest
  /// first, each to be applied search_latency_keyframes after its keyframe.
  std::deque<std::future<LoopOutcome>> pending_;
  std::size_t jobs_ = 0;  ///< searches prepared so far
  std::shared_ptr<KeptLoops> kept_by_jobs_ = std::make_shared<KeptLoops>();
  ScanAnchor anchor_;
  std::size_t scans_ = 0;
  /// The keyframes of the last refine_map_path_m in the newest one's frame,
  /// built when first needed after a keyframe or a closure.
  std::unique_ptr<LineMap> recent_map_;
  OdometryModel odometry_model_;
  OdometryEdges odometry_edges_;
  PathConstraints path_constraints_;
  /// Runs the searches (and their loops' tests) one after the other on one
  /// thread of its own. A job holds copies (LoopSearch, the graph), nothing
  /// of the back end; destroying the worker drops the queued jobs and joins
  /// the running one.
  common::SerialWorker<LoopOutcome> worker_;
};

}  // namespace pmap::poses
