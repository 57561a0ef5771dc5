// Scan-to-submap matching for loop closure, without a good initial guess:
//  1. a correlative search (Olson, ICRA 2009): the submap's points make a
//     likelihood grid (a Gaussian of each cell's distance to the nearest
//     point); every pose of a window (x, y, theta) is scored by the mean
//     likelihood of the query points. The search is exhaustive over angles
//     and branch-and-bound in translation (as Hess et al., ICRA 2016): grids
//     max-pooled over 2^h x 2^h cells bound the score of every offset of a
//     block from above, so blocks are split best first and dropped as soon
//     as their bound is no better than the best exact score found (or the
//     acceptance threshold): the result is the exact best cell offset;
//  2. the caller narrows down coarse to fine: a coarse grid over the whole
//     window, then a fine grid around the coarse best (loop_closure.cpp).
// The result is exact on the search lattice (resolution_m, the angle step);
// a point-to-line refinement was tried on the Radish logs and left out: on
// 1-degree scans with partial overlap it slid along corridors by decimetres.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <string>
#include <vector>

#include "pmap/poses/pooled_grid.h"
#include "pmap/poses/pose_graph.h"

namespace pmap::poses {

struct ScanMatchOptions {
  double resolution_m = 0.05;       ///< likelihood grid cell (m)
  double sigma_m = 0.05;            ///< likelihood and point-to-line noise (m)
  int levels = 7;                   ///< branch-and-bound levels: blocks of up to 2^(levels-1) cells
  double min_angle_step_deg = 0.2;  ///< the angle step moves the farthest point one cell,
  double max_angle_step_deg = 1.0;  ///< within these bounds
  /// Consecutive reference points (a scan's neighbouring beams) closer than
  /// this are joined by a line before the grid is built (free_space.h
  /// densified).
  double max_gap_m = 0.25;
  double query_voxel_m = 0.1;  ///< query points thinned to one per voxel
  int max_query_points = 400;  ///< and to at most this many
  bool validate(std::string* why) const;
};

/// Where to search: around `guess`, +-linear_m in x and y, +-angular_deg.
struct MatchWindow {
  Pose2 guess;
  double linear_m = 1.0;
  double angular_deg = 10.0;
};

struct ScanMatch {
  bool found = false;
  Pose2 pose;        ///< of the query's frame in the reference's frame
  double score = 0;  ///< mean likelihood of the query points, [0, 1]
};

/// A submap prepared for matching: its likelihood grid, max-pooled.
class ScanMatcher {
 public:
  ScanMatcher(const std::vector<Eigen::Vector2d>& reference, ScanMatchOptions options);

  /// The best pose of the window's lattice, if it scores more than
  /// `min_score`. `found` is false when there is none, or the query or the
  /// reference is empty.
  ScanMatch match(const std::vector<Eigen::Vector2d>& query, const MatchWindow& window,
                  double min_score = 0.0) const;
  /// As match(), but the best pose of the window outside `excluded` (a pose
  /// within excluded.linear_m in x and y and excluded.angular_deg of
  /// excluded.guess does not count): the runner-up of an ambiguous place.
  ScanMatch matchOutside(const std::vector<Eigen::Vector2d>& query, const MatchWindow& window,
                         const MatchWindow& excluded, double min_score) const;
  /// Whether matchOutside() would find a pose: the search stops at the first
  /// pose outside `excluded` scoring more than `min_score`, looking at the
  /// angles of excluded's heading first, one at a time (on the aliasing
  /// world's loop searches, 0.44 s instead of 1.32 s for its 217 ambiguous
  /// places; the same on ACES, where few are).
  bool anyOutside(const std::vector<Eigen::Vector2d>& query, const MatchWindow& window,
                  const MatchWindow& excluded, double min_score) const;
  /// As anyOutside(), but the poses within band_m of the line through
  /// excluded.guess along `axis` (a unit x-y direction), and within
  /// excluded.angular_deg of its heading, do not count either: whether a
  /// place is ambiguous other than along that line (a corridor's axis, a
  /// row of doors).
  bool anyOutsideBand(const std::vector<Eigen::Vector2d>& query, const MatchWindow& window,
                      const MatchWindow& excluded, const Eigen::Vector2d& axis, double band_m,
                      double min_score) const;

 private:
  struct Band {
    Eigen::Vector2d axis = Eigen::Vector2d::UnitX();
    double half_width_m = -1.0;  ///< < 0: no band
  };
  ScanMatch search(const std::vector<Eigen::Vector2d>& query, const MatchWindow& window,
                   const MatchWindow& excluded, double min_score, bool first_only,
                   const Band& band) const;
  struct Grid {
    double x0 = 0, y0 = 0;  ///< lower corner (m)
    /// level h: the likelihood max-pooled over [c, c + 2^h) x [r, r + 2^h);
    /// level 0 is the likelihood itself.
    PooledGrid levels;
    float at(int h, int c, int r) const { return levels.at(h, c, r); }
  };
  struct Search;
  void buildGrid(const std::vector<Eigen::Vector2d>& reference);

  ScanMatchOptions options_;
  Grid grid_;
};

}  // namespace pmap::poses
