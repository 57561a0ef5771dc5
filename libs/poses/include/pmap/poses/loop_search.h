// One keyframe's loop-closure search (loop_closure.h): the candidates'
// submaps and the query are copied out of the back end when the keyframe is
// added, so that matching them touches no shared state and can run on a
// worker thread while the front end goes on ([Poses]
// loop_search_latency_keyframes). Each candidate is verified by a
// coarse-to-fine correlative match (scan_matcher.h), a uniqueness test and a
// free-space test; the best verified one is the result.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "pmap/poses/free_space.h"
#include "pmap/poses/loop_closure_options.h"
#include "pmap/poses/pose_graph.h"
#include "pmap/poses/scan_matcher.h"

namespace pmap::poses {

/// An older keyframe to match against.
struct LoopCandidate {
  std::size_t older = 0;     ///< keyframe index
  Pose2 guess;               ///< the newest keyframe in older's frame, from the graph
  std::vector<Rays> submap;  ///< the scans around it (optimised poses), in older's frame
};

/// What a search needs, copied at the keyframe.
struct LoopSearch {
  std::size_t newest = 0;  ///< the keyframe searched for
  double radius_m = 0;     ///< the search window (loop_closure.h)
  double angle_deg = 0;
  std::vector<Rays> query;  ///< the newest keyframe's recent scans (front-end poses), its frame
  std::vector<LoopCandidate> candidates;
};

/// What it found.
struct LoopSearchResult {
  std::size_t candidates = 0;           ///< verified by a match
  std::size_t rejected_match = 0;       ///< no pose of the window scored min_score
  std::size_t rejected_ambiguous = 0;   ///< another pose scored nearly as well / window edge
  std::size_t rejected_free_space = 0;  ///< the best pose contradicts the beams' free space
  /// Verified although ambiguous along one line (accept_axis_ambiguity).
  std::size_t axis_only = 0;
  bool found = false;  ///< a verified match: edge and match are set
  PoseEdge edge;       ///< older -> newest (loopEdge)
  ScanMatch match;
  /// The match is ambiguous along this unit x-y direction (the older
  /// keyframe's frame), which its edge leaves free; zero when it is not.
  Eigen::Vector2d free_axis = Eigen::Vector2d::Zero();
  double search_s = 0;  ///< wall time of the search
};

/// The loop edge older -> (to be set) of a verified correlative match of
/// `query` (the newest keyframe's points, its frame) at `match` in
/// `candidate`'s frame (doc/poses.md, "Loop edges"). With refine_loops the
/// match is refined point-to-line on the candidate's submap (scan_refiner.h)
/// and the edge is the points' own estimate, with the information
///   (Sigma_match + (information_scale H_points + L_flat)^-1)^-1,
/// Sigma_match = diag(loop_sigma_m^2, loop_sigma_m^2, loop_sigma_deg^2): the
/// match's own error (its 5 cm lattice, any scene) plus what the points
/// leave open (a corridor's axis). Without it (or too few matched points):
/// the match, with the information Sigma_match^-1. A non-zero `free_axis`
/// (unit, x-y), or with refine_loops the translation the points constrain
/// least when it has less than min_axis_ratio of the other's information,
/// is left free: the edge has the match's pose along it and no information
/// there but the floor's.
PoseEdge loopEdge(const LoopCandidate& candidate, const std::vector<Eigen::Vector2d>& query,
                  const Pose2& match, const LoopClosureOptions& options,
                  const Eigen::Vector2d& free_axis = Eigen::Vector2d::Zero());

LoopSearchResult runLoopSearch(const LoopSearch& search, const LoopClosureOptions& options,
                               const ScanMatchOptions& match_options);

}  // namespace pmap::poses
