// Free-space evidence for verifying a scan match (loop closure). A
// correlative score only rewards points that land near points; a wrong
// match that slides a corridor onto its neighbour or puts the robot inside
// a block can still score well where the two local maps overlap little.
// Every beam also says "nothing here" along its way: a match is suspect when
// one side's points land where the other side's beams passed freely, or
// when its beams reach the other side's surfaces from behind (a corridor's
// inside corner laid onto a block's outside corner: the points agree, the
// sides they were seen from do not).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "pmap/poses/pose_graph.h"

namespace pmap::poses {

/// One scan in some frame: the sensor's origin and the beams' end points,
/// in beam order.
struct Rays {
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();
  std::vector<Eigen::Vector2d> ends;
};

/// A grid of what a set of scans saw: free (crossed by a beam), surface (an
/// end point, the line between neighbouring end points closer than
/// max_gap_m, and the cells around them), or unknown. Beams count up to
/// kMaxRangeM.
class FreeSpace {
 public:
  static constexpr double kMaxRangeM = 20.0;

  /// `cell_m`: grid cell; `margin_m`: how much of each beam's end is not
  /// taken as free (range noise, the sensor's offset from the robot origin);
  /// `max_gap_m`: neighbouring end points closer than this are one surface.
  FreeSpace(const std::vector<Rays>& scans, double cell_m, double margin_m, double max_gap_m);

  /// The fraction of `points` (in this frame) that lie in free cells.
  double conflict(const std::vector<Eigen::Vector2d>& points) const;

  /// Of the beams of `scans` (in this frame) that end on a surface cell, the
  /// fraction that arrive through free space (the point margin_m and two
  /// cells before the end is free): seen from the same side. 1 when none
  /// ends on a surface.
  double sameSide(const std::vector<Rays>& scans) const;

 private:
  enum Cell : std::uint8_t { kUnknown = 0, kFree = 1, kNearSurface = 2, kSurface = 3 };
  Cell at(const Eigen::Vector2d& p) const;
  void mark(const Eigen::Vector2d& p, Cell c);

  double cell_m_;
  double margin_m_;
  Eigen::Vector2d lo_ = Eigen::Vector2d::Zero();
  int cols_ = 0;
  int rows_ = 0;
  std::vector<Cell> cells_;
};

/// `scans` given in `pose`'s frame, in the frame `pose` lives in.
std::vector<Rays> moved(const std::vector<Rays>& scans, const Pose2& pose);
/// Every end point of `scans`.
std::vector<Eigen::Vector2d> allEnds(const std::vector<Rays>& scans);
/// Consecutive points closer than `max_gap` joined by points every `step`:
/// a 1-degree scan samples a wall 10 m away every 17 cm, and a grid must
/// see the wall, not the samples.
std::vector<Eigen::Vector2d> densified(const std::vector<Eigen::Vector2d>& points, double max_gap,
                                       double step);

}  // namespace pmap::poses
