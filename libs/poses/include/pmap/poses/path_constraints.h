// Keyframe-to-submap constraints along the path (doc/poses.md, "Path
// constraints"). The chain of keyframe edges is matched against the last few
// metres only, so in a long corridor it bends slowly, the same way on every
// lap (the loops tie the laps together, not the corridor straight). Each new
// keyframe is therefore also matched, point-to-line, against the submap of
// the keyframes around the one spacing_m, 2 spacing_m, ... count spacing_m
// back along the path (placed with the graph's poses, in that keyframe's
// frame), started from the graph's relative pose and with the points alone
// (a flat prior, taken out again); the result is an edge between the two
// whose information is the match's (information_scale of the points'),
// without the direction along the line between them where the points
// hardly see it (min_along_ratio).
// A match the graph disagrees with by more than max_chi2 is dropped (partial
// overlap, a corner matched to the wrong wall). The edges enter the graph for
// its last solve, at the end of the input, under the robust loss of loop
// edges: in the graph during the run they made it too stiff for the loops
// (ACES: 92 -> 46 loops accepted, loop relations 0.07 -> 0.57 m).
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "pmap/poses/keyframe.h"
#include "pmap/poses/pose_graph.h"
#include "pmap/poses/scan_refiner.h"

namespace pmap::poses {

struct PathConstraintOptions {
  int count = 4;                    ///< constraints per keyframe (0: none)
  double spacing_m = 5.0;           ///< path between the keyframes they reach back to (m)
  double submap_half_path_m = 1.0;  ///< the submap: keyframes within this path of the one (m)
  /// The submap's lines join neighbouring beams up to this far apart (m;
  /// the keyframe edges' 0.5 m gives far walls no lines: with 1-degree
  /// beams a wall 1.2 m to the side has its beams 0.5 m apart 6 m ahead, 2 m
  /// apart 12 m ahead, and a keyframe 10-20 m on sees only the far part).
  double max_gap_m = 2.0;
  double max_chi2 = 11.34;  ///< e^T I e against the graph when made (3 dof, 99 %)
  /// The match's information along the line between the two keyframes is
  /// kept only when it is at least this share of the information across
  /// it (otherwise it is noise: path_constraints.cpp).
  double min_along_ratio = 0.01;
  bool validate(std::string* why) const;
};

class PathConstraints {
 public:
  PathConstraints(PathConstraintOptions options, ScanRefineOptions refine);

  /// The newest keyframe `id` matched against the submaps behind it, with
  /// the graph as it is now (its node `id` placed).
  void add(std::size_t id, const std::vector<Keyframe>& keyframes, const PoseGraph& graph);

  const std::vector<PoseEdge>& edges() const { return edges_; }
  std::size_t rejected() const { return rejected_; }

 private:
  const LineMap& submap(std::size_t centre, const std::vector<Keyframe>& keyframes,
                        const PoseGraph& graph);

  PathConstraintOptions options_;
  ScanRefineOptions refine_;
  std::vector<PoseEdge> edges_;
  std::size_t rejected_ = 0;
  /// Submaps by their centre keyframe, built once each and dropped when no
  /// later keyframe can reach back to them.
  std::map<std::size_t, LineMap> submaps_;
};

}  // namespace pmap::poses
