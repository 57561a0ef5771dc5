// The options of loop closure ([Poses] loop_*, doc/configuration.md), shared
// by the back end (loop_closure.h) and its search (loop_search.h).
#pragma once

#include <string>

#include "pmap/poses/odometry_model.h"
#include "pmap/poses/path_constraints.h"
#include "pmap/poses/scan_refiner.h"

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
  /// ... unless all those poses lie on one line through the best (along the
  /// translation the walls constrain least, within two cells across and
  /// 5 deg): then the loop is kept, its edge free along that line
  /// (loop_search.h, loopEdge).
  bool accept_axis_ambiguity = false;
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
  /// A loop's innovation, the rise of the graph's objective (times 2) when
  /// the graph follows it: e^T (Sigma_graph + Sigma_loop)^-1 e for Gaussian
  /// edges, chi2 with 3 dof (11.34: 99 %). Above it the loop is refused.
  double max_chi2 = 11.34;
  double loop_sigma_m = 0.05;   ///< a loop edge's standard deviation (m)
  double loop_sigma_deg = 1.0;  ///< ... and in heading (deg)
  /// A verified match refined point-to-line on the candidate's submap: the
  /// loop edge is the points' estimate, and its information adds to the
  /// sigmas above what the points leave open (loop_search.h, loopEdge).
  bool refine_loops = true;
  /// ... except along the translation the points constrain least when its
  /// information is below this share of the other's (a corridor's axis,
  /// whose information is the normals' noise, path_constraints.h's
  /// min_along_ratio): there the edge has the match's pose and none of the
  /// points' information, [0, 1].
  double min_axis_ratio = 0.01;
  /// The front end's relative pose as an edge's prior (without calibrated
  /// odometry): translation sigma per metre moved, heading sigma plus 5 %
  /// of the turn.
  double odometry_sigma_fraction = 0.05;
  double odometry_sigma_deg = 0.5;
  double loop_loss_scale = 1.0;  ///< Cauchy scale of loop edges (whitened)
  /// 0: each keyframe's search runs when the keyframe is added. N > 0: it
  /// is queued on one worker thread (one search at a time, in keyframe
  /// order) and its result is applied when the keyframe N keyframes later is
  /// added (waiting for it if need be), so the front end goes on meanwhile.
  /// The same input gives the same result whatever the threads' speed.
  int search_latency_keyframes = 1;
  /// Tests and debugging (not read from the ini): each loop the worker
  /// tested is tested again on the front end's own graph when applied, and
  /// std::logic_error is thrown when the two disagree (beyond 5 mm or 5 mrad
  /// in a node, 0.01 + 0.1 % in the innovation): the worker's copy with
  /// its kept loops must be the front end's graph without the newest
  /// keyframes.
  bool verify_worker_tests = false;
  /// Each keyframe's edge from the previous one refined point-to-line
  /// against the keyframes of the last refine_map_path_m, placed with the
  /// graph's poses (scan_refiner.h); its information from that match.
  bool refine_keyframes = true;
  double refine_map_path_m = 5.0;
  /// With refine_keyframes: every pose-laser scan between keyframes, from
  /// the second keyframe on, refined the same way (held to the front end's
  /// pose relative to the keyframe).
  bool refine_scans = true;
  ScanRefineOptions refine;
  /// With refine_keyframes and a log with odometry: keyframe edges and
  /// scans held to the calibrated wheel odometry instead of the front end's
  /// relative pose (odometry_model.h).
  OdometryModelOptions odometry;
  /// With refine_keyframes: keyframe-to-submap edges along the path, for the
  /// graph's last solve (path_constraints.h).
  PathConstraintOptions path;
  /// The ICP front end's point map keeps the points within this distance
  /// of the robot (m), trimmed every quarter of it travelled, and is rebuilt
  /// after every accepted loop from the keyframes within it, placed by the
  /// optimised graph (loop_closing_stage.h); 0: MRPT's own global map, never
  /// trimmed nor rebuilt. 20 m: doc/poses.md, "The front end's map".
  double front_map_radius_m = 20.0;
  /// The rebuilt map's points: at least this far apart along their scan (m;
  /// MRPT's minDistBetweenLaserPoints does the same for the scans it inserts).
  double front_map_spacing_m = 0.05;
  bool validate(std::string* why) const;
};

}  // namespace pmap::poses
