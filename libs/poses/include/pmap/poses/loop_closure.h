// The pose graph back end behind the ICP front end (doc/poses.md, "Loop
// closure"): keyframes every keyframe_distance_m / keyframe_angle_deg of
// front-end motion, each linked to the previous one by the front end's
// relative pose (an odometry edge whose information matrix comes from a
// scan-to-scan match), and loop edges to older keyframes found by
// scan-to-submap matching.
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
// alias along their axis), when the beams' free space agrees, and when,
// after the graph is solved with it (Cauchy
// loss on loop edges), its residual stays below max_chi2: a loop that the
// rest of the graph cannot agree with is taken out again. The work per
// keyframe is bounded by the candidate count and the window's size.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "pmap/poses/free_space.h"
#include "pmap/poses/pose_graph.h"
#include "pmap/poses/scan_matcher.h"

namespace pmap::poses {

struct LoopClosureOptions {
  bool enabled = false;              ///< [Poses] loop_closure
  double keyframe_distance_m = 0.5;  ///< a keyframe every so much front-end travel (m)
  double keyframe_angle_deg = 15.0;  ///< ... or turn (deg)
  /// A loop joins keyframes at least this far apart along the path (m):
  /// closer ones are the front end's own business.
  double min_loop_path_m = 12.0;
  double search_radius_m = 1.0;                ///< search window radius right after a closure (m)
  double search_growth = 0.05;                 ///< its growth per metre travelled since (m/m)
  double max_search_radius_m = 8.0;            ///< its cap (m)
  double search_angle_deg = 10.0;              ///< angular window right after a closure (deg)
  double search_angle_growth_deg_per_m = 0.2;  ///< its growth (deg/m)
  double max_search_angle_deg = 40.0;          ///< its cap (deg)
  int candidates_per_keyframe = 3;             ///< candidates verified per keyframe, at most
  double submap_path_m = 8.0;  ///< a candidate's submap: keyframes within +-half along the path (m)
  double query_path_m = 3.0;   ///< the query: keyframes this far back along the path (m)
  /// Mean likelihood of the query points on the fine grid (sigma 5 cm) to
  /// accept a match, [0, 1]. On the ACES log true loops score 0.4-0.63.
  double min_score = 0.4;
  /// A match is refused when another pose of the search window, at least
  /// ambiguity_distance_m or 5 deg away, scores more than max_ambiguity of
  /// the best, (0, 1]: the place is ambiguous (a corridor's axis).
  double max_ambiguity = 0.9;
  double ambiguity_distance_m = 1.0;
  /// A match is refused when more than this fraction of one side's points
  /// lie where the other side's beams passed freely (free_space.h), [0, 1].
  /// 0.1: the simulated ring's one aliased match had 0.1-0.25, its true
  /// ones at most 0.03 (ACES's, unverified, 0.01-0.3: see doc/poses.md).
  double max_free_space_conflict = 0.1;
  double free_space_margin_m = 0.3;  ///< the end of each beam not taken as free (m)
  /// ... and when, of the beams that end on the other side's surfaces, the
  /// fraction arriving through its free space is below this share of the
  /// same fraction within each side (surfaces seen from behind), [0, 1].
  double min_same_side_ratio = 0.6;
  double max_chi2 = 11.34;                ///< a loop's e^T I e after solving (3 dof, 99 %)
  double loop_sigma_m = 0.05;             ///< a loop edge's standard deviation (m)
  double loop_sigma_deg = 1.0;            ///< ... and in heading (deg)
  double odometry_sigma_fraction = 0.05;  ///< odometry edges: translation sigma per metre moved
  double odometry_sigma_deg = 0.5;        ///< odometry edges: heading sigma, plus 5 % of the turn
  double loop_loss_scale = 1.0;           ///< Cauchy scale of loop edges (whitened)
  bool validate(std::string* why) const;
};

struct Keyframe {
  double t = 0;                         ///< s
  Pose2 front;                          ///< the front end's pose (its own frame)
  double path_m = 0;                    ///< front-end path length up to here
  std::vector<Eigen::Vector2d> points;  ///< the pose laser's points, robot frame
};

/// One accepted loop closure.
struct LoopClosure {
  std::size_t older = 0;  ///< keyframe indices
  std::size_t newer = 0;
  double older_t = 0;  ///< time of the older keyframe (s)
  double t = 0;        ///< time of the newer keyframe (s)
  Pose2 measurement;   ///< the newer keyframe's pose in the older one's frame (the match)
  double score = 0;
  double moved_m = 0;   ///< how far the newest keyframe moved when the graph was solved
  double solve_ms = 0;  ///< that solve's wall time
};

struct LoopClosureStats {
  std::size_t keyframes = 0;
  std::size_t candidates = 0;           ///< verified by a scan-to-submap match
  std::size_t rejected_match = 0;       ///< no pose of the window scored min_score
  std::size_t rejected_ambiguous = 0;   ///< another pose of the window scored nearly as well
  std::size_t rejected_free_space = 0;  ///< the best pose contradicts the beams' free space
  std::size_t rejected_chi2 = 0;        ///< taken out again after solving
  std::size_t accepted = 0;
  double search_s = 0;  ///< wall time of candidate search and matching
  double solve_s = 0;   ///< wall time of the graph solves
};

class LoopClosingBackEnd {
 public:
  explicit LoopClosingBackEnd(LoopClosureOptions options, ScanMatchOptions match = {});

  /// The front end's pose of a pose-laser scan at `t` and the scan's points
  /// (robot frame). Returns true when a loop closure moved the graph.
  bool addScan(double t, const Pose2& front, std::vector<Eigen::Vector2d> points);

  /// The world pose of a front-end pose taken while `keyframe` was the newest.
  Pose2 corrected(std::size_t keyframe, const Pose2& front) const;
  /// The newest keyframe's index; only meaningful once there is one.
  std::size_t newest() const { return keyframes_.size() - 1; }
  bool empty() const { return keyframes_.empty(); }

  const std::vector<Keyframe>& keyframes() const { return keyframes_; }
  const PoseGraph& graph() const { return graph_; }
  const std::vector<LoopClosure>& closures() const { return closures_; }
  const LoopClosureStats& stats() const { return stats_; }
  const LoopClosureOptions& options() const { return options_; }

 private:
  bool isKeyframe(const Pose2& front) const;
  void addKeyframe(double t, const Pose2& front, std::vector<Eigen::Vector2d> points);
  Eigen::Matrix3d odometryInformation(std::size_t from, std::size_t to) const;
  bool closeLoop();
  std::vector<std::size_t> candidates(double radius) const;
  enum class Verdict { kMatched, kNoMatch, kAmbiguous, kFreeSpaceConflict };
  std::vector<Rays> scansAround(std::size_t centre, double half_path_m, bool optimised,
                                bool only_older) const;
  bool freeSpaceAgrees(const std::vector<Rays>& submap, const std::vector<Rays>& query,
                       const Pose2& match) const;
  Verdict tryCandidate(std::size_t older, const std::vector<Rays>& query_scans, double radius,
                       double angle_deg, PoseEdge& edge, ScanMatch& match) const;
  bool acceptAfterSolve(const PoseEdge& edge, const ScanMatch& match);

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
};

}  // namespace pmap::poses
