#include "pmap/poses/loop_search.h"

#include <mrpt/core/bits_math.h>
#include <Eigen/LU>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "pmap/poses/odometry_model.h"
#include "pmap/poses/scan_refiner.h"

namespace pmap::poses {
namespace {

enum class Verdict { kMatched, kNoMatch, kAmbiguous, kFreeSpaceConflict };

// A match is refused when either side's points land where the other side's
// beams passed freely (free_space.h).
bool freeSpaceAgrees(const std::vector<Rays>& submap, const std::vector<Rays>& query,
                     const Pose2& match, const LoopClosureOptions& options,
                     const ScanMatchOptions& match_options) {
  const double cell = 2.0 * match_options.resolution_m;
  const double margin = options.free_space_margin_m, gap = match_options.max_gap_m;
  const FreeSpace submap_space(submap, cell, margin, gap);
  const FreeSpace query_space(query, cell, margin, gap);
  const std::vector<Rays> query_there = moved(query, match);
  const std::vector<Rays> submap_here = moved(submap, inverse(match));
  const double conflict = std::max(submap_space.conflict(allEnds(query_there)),
                                   query_space.conflict(allEnds(submap_here)));
  const double same_side =
      std::min(submap_space.sameSide(query_there), query_space.sameSide(submap_here));
  // Relative to how consistent each side is with itself: real scans, with
  // clutter and 1-degree beams, agree with themselves less than simulated ones.
  const double own = std::min(submap_space.sameSide(submap), query_space.sameSide(query));
  return conflict <= options.max_free_space_conflict &&
         same_side >= options.min_same_side_ratio * own;
}

Eigen::Vector3d asTranslation(const Eigen::Vector2d& axis) {
  return {axis.x(), axis.y(), 0.0};
}

// The edge's measurement with the match's pose along `axis` (its
// information there is the caller's).
void freeAlong(const Eigen::Vector2d& axis, const Pose2& match, PoseEdge& edge) {
  const double along =
      axis.dot(Eigen::Vector2d(edge.measurement.x - match.x, edge.measurement.y - match.y));
  edge.measurement.x -= along * axis.x();
  edge.measurement.y -= along * axis.y();
}

// The translation the submap's lines constrain least at `match` (a
// corridor's axis); zero when too few points match to tell.
Eigen::Vector2d weakestAxis(const LoopCandidate& candidate,
                            const std::vector<Eigen::Vector2d>& query, const Pose2& match,
                            const LoopClosureOptions& options) {
  const RefinedPose r = refinePose(LineMap(candidate.submap, options.refine), query, match,
                                   1e-3 * flatPrior(), options.refine);
  return r.refined ? Eigen::Vector2d(weakestTranslation(r.data_information).direction.head<2>())
                   : Eigen::Vector2d::Zero();
}

// Coarse to fine (Olson 2009): the whole window on a coarse, blurred grid
// (4x the cell and sigma, 80 % of the score), then a small window around its
// best pose on the fine grid.
Verdict tryCandidate(const LoopCandidate& candidate, const std::vector<Eigen::Vector2d>& query,
                     const LoopSearch& search, const LoopClosureOptions& options,
                     const ScanMatchOptions& match_options, ScanMatch& match,
                     Eigen::Vector2d& free_axis) {
  const std::vector<Eigen::Vector2d> submap = allEnds(candidate.submap);
  ScanMatchOptions coarse = match_options;
  coarse.resolution_m = 4.0 * match_options.resolution_m;
  coarse.sigma_m = 4.0 * match_options.sigma_m;
  coarse.max_angle_step_deg = 1.0;
  coarse.min_angle_step_deg = 0.5;
  coarse.max_query_points = 150;
  MatchWindow whole;
  whole.guess = candidate.guess;
  whole.linear_m = search.radius_m;
  whole.angular_deg = search.angle_deg;
  const ScanMatch rough = ScanMatcher(submap, coarse).match(query, whole, 0.8 * options.min_score);
  if (!rough.found) {
    return Verdict::kNoMatch;
  }
  MatchWindow near_rough;
  near_rough.guess = rough.pose;
  near_rough.linear_m = 2.0 * coarse.resolution_m;
  near_rough.angular_deg = 2.0;
  const ScanMatcher fine(submap, match_options);
  match = fine.match(query, near_rough, options.min_score);
  if (!match.found) {
    return Verdict::kNoMatch;
  }
  // A best pose on the window's edge is no verified maximum: the score may
  // rise beyond it (the search was cut off there).
  const double edge_m = whole.linear_m - 2.0 * match_options.resolution_m;
  if (std::abs(match.pose.x - whole.guess.x) >= edge_m ||
      std::abs(match.pose.y - whole.guess.y) >= edge_m ||
      std::abs(wrapAngle(match.pose.theta - whole.guess.theta)) >=
          mrpt::DEG2RAD(whole.angular_deg - 1.0)) {
    return Verdict::kAmbiguous;
  }
  // A place that looks the same elsewhere in the search window (a corridor's
  // axis, a row of doors) gives no loop: the runner-up, at least
  // ambiguity_distance_m or 5 deg from the best, must score clearly less...
  MatchWindow near_best;
  near_best.guess = match.pose;
  near_best.linear_m = options.ambiguity_distance_m;
  near_best.angular_deg = 5.0;
  const double runner_up = options.max_ambiguity * match.score;
  free_axis = Eigen::Vector2d::Zero();
  if (fine.anyOutside(query, whole, near_best, runner_up)) {
    // ... unless every such pose lies on the line through the best along
    // the translation the walls constrain least (its heading within 5 deg,
    // two cells across): then the place is known across that line and in
    // heading, and the edge leaves the line free.
    if (!options.accept_axis_ambiguity) {
      return Verdict::kAmbiguous;
    }
    const Eigen::Vector2d axis = weakestAxis(candidate, query, match.pose, options);
    if (axis.isZero() || fine.anyOutsideBand(query, whole, near_best, axis,
                                             2.0 * match_options.resolution_m, runner_up)) {
      return Verdict::kAmbiguous;
    }
    free_axis = axis;
  }
  if (!freeSpaceAgrees(candidate.submap, search.query, match.pose, options, match_options)) {
    return Verdict::kFreeSpaceConflict;
  }
  return Verdict::kMatched;
}

}  // namespace

PoseEdge loopEdge(const LoopCandidate& candidate, const std::vector<Eigen::Vector2d>& query,
                  const Pose2& match, const LoopClosureOptions& options,
                  const Eigen::Vector2d& free_axis) {
  PoseEdge edge;
  edge.from = candidate.older;
  edge.loop = true;
  edge.measurement = match;
  const double st = options.loop_sigma_m, sr = mrpt::DEG2RAD(options.loop_sigma_deg);
  const Eigen::Matrix3d match_information =
      Eigen::Vector3d(1 / (st * st), 1 / (st * st), 1 / (sr * sr)).asDiagonal();
  // A thousandth of the flat prior (sigma 32 m, 160 deg), as the path
  // constraints' floor: only so that the solve and the inverse below exist
  // where the points say nothing.
  const Eigen::Matrix3d flat = 1e-3 * flatPrior();
  const bool has_free_axis = !free_axis.isZero();
  edge.information =
      has_free_axis
          ? Eigen::Matrix3d(withoutDirection(match_information, asTranslation(free_axis)) + flat)
          : match_information;
  if (!options.refine_loops) {
    return edge;
  }
  const RefinedPose r =
      refinePose(LineMap(candidate.submap, options.refine), query, match, flat, options.refine);
  if (!r.refined) {
    return edge;
  }
  // The points' own estimate, off the correlative lattice where the walls
  // constrain it (odometry_model.h).
  edge.measurement = dataEstimate(r.pose, r.data_information, match, flat);
  // Along a bare corridor's axis the points' information is only what their
  // normals' noise makes up, and their estimate there wanders with it (by a
  // rounding's worth of difference in the solve: 1.3 cm with one compiler,
  // 7.6 cm with another, in LoopEdge.ACorridorsAxisGetsNoInformation). That
  // direction is dropped, as the path constraints drop theirs, and the edge
  // keeps the match's pose along it. A match ambiguous along a line
  // (tryCandidate) leaves that line free in the same way.
  Eigen::Matrix3d data = r.data_information;
  const WeakestTranslation weak = weakestTranslation(data);
  const Eigen::Vector2d axis = has_free_axis ? free_axis
                               : weak.ratio < options.min_axis_ratio
                                   ? Eigen::Vector2d(weak.direction.head<2>())
                                   : Eigen::Vector2d::Zero();
  if (!axis.isZero()) {
    data = withoutDirection(data, asTranslation(axis));
    freeAlong(axis, match, edge);
  }
  //   Sigma_loop = Sigma_match + (s H_points + L_flat)^-1
  const Eigen::Matrix3d points = options.refine.information_scale * data + flat;
  const Eigen::Matrix3d information = (match_information.inverse() + points.inverse()).inverse();
  edge.information = 0.5 * (information + information.transpose());
  return edge;
}

LoopSearchResult runLoopSearch(const LoopSearch& search, const LoopClosureOptions& options,
                               const ScanMatchOptions& match_options) {
  const auto t0 = std::chrono::steady_clock::now();
  LoopSearchResult r;
  const std::vector<Eigen::Vector2d> query = allEnds(search.query);  // the same for every candidate
  const LoopCandidate* best = nullptr;
  for (const LoopCandidate& c : search.candidates) {
    ++r.candidates;
    ScanMatch match;
    Eigen::Vector2d free_axis;
    const Verdict v = tryCandidate(c, query, search, options, match_options, match, free_axis);
    if (v != Verdict::kMatched) {
      ++(v == Verdict::kNoMatch     ? r.rejected_match
         : v == Verdict::kAmbiguous ? r.rejected_ambiguous
                                    : r.rejected_free_space);
      continue;
    }
    r.axis_only += free_axis.isZero() ? 0 : 1;
    // The best verified candidate, one that fixes every direction first.
    const bool fixes_all = free_axis.isZero(), best_fixes_all = r.found && r.free_axis.isZero();
    if (fixes_all != best_fixes_all ? fixes_all : match.score > r.match.score) {
      r.found = true;
      r.match = match;
      r.free_axis = free_axis;
      best = &c;
    }
  }
  if (r.found) {
    r.edge = loopEdge(*best, query, r.match.pose, options, r.free_axis);
    r.edge.to = search.newest;
  }
  r.search_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace pmap::poses
