// Seam gaps: where two non-parallel ground-truth surfaces meet (a wall under
// the ceiling, two walls at a corner or a junction), how far the map's
// rectangle of one stops short of, or overshoots, the other map surface's
// plane along the shared edge (doc/evaluation.md, "Seams").
#pragma once

#include <vector>

#include "pmap/eval/ground_truth.h"
#include "pmap/eval/surface_files.h"

namespace pmap::eval {

struct SeamOptions {
  double min_angle_deg = 30.0;  ///< normals closer than this are parallel: no seam
  double on_plane_m = 0.01;     ///< a ground-truth edge this close to the other plane is shared
  double min_shared_m = 0.1;    ///< ... along at least this length (not a touch at a corner)
};

/// One side of a ground-truth seam: surface gt_id's edge ends on gt_other's
/// plane. For a corner both sides count, for a junction (one surface's edge
/// on the middle of the other) one.
struct SeamSide {
  int gt_id = -1, gt_other = -1;
  int map_id = -1, map_other = -1;  ///< their primary map surfaces
  /// In-plane distance of map_id's edge to the line where the two map
  /// planes meet, the mean at the two ends of the shared part (the
  /// ground-truth edge's extent beside gt_other's rectangle): > 0 a gap (the edge stops short),
  /// < 0 an overlap (the edge overshoots the other plane).
  double gap_m = 0;
};

/// A ground-truth rectangle's edge ending on another's plane (shared edges).
struct GtSeam {
  int gt_id = -1, gt_other = -1;
  int edge = 0;  ///< edge k joins corners k and (k + 1) % 4
};

/// The shared edges among `ids` (ground-truth rectangles of gt).
std::vector<GtSeam> groundTruthSeams(const GroundTruth& gt, const std::vector<int>& ids,
                                     const SeamOptions& options = {});

/// The edges of the doors among `ids` that bound their wall's opening: a
/// rectangle with a `parent` parallel to it, each edge whose midpoint,
/// projected onto the parent, lies inside the parent's rectangle (more than
/// `on_plane_m` from its boundary): the door's top and sides, not its foot
/// on the floor. As GtSeam {door, parent, edge}, for closedReference.
std::vector<GtSeam> openingEdges(const GroundTruth& gt, const std::vector<int>& ids,
                                 const SeamOptions& options = {});

/// The reference rectangle `clipped` (what the laser saw of `rect`, corners
/// in rect's order) with each edge that is a shared edge of `rect` (in
/// `seams`) moved onto it when it lies within `reach_m`: what a map that
/// closes its seams should reach (corner_error_closed_m).
std::array<Eigen::Vector3d, 4> closedReference(const GtRectangle& rect,
                                               const std::array<Eigen::Vector3d, 4>& clipped,
                                               const std::vector<GtSeam>& seams, double reach_m);

/// The seam sides of ground-truth pairs whose both surfaces are matched:
/// `primary` maps a ground-truth id to its primary map surface (in the
/// ground-truth frame). The map edge of a side is the map rectangle's edge
/// nearest the ground-truth edge's line among those along it (within 30 deg).
std::vector<SeamSide> seamSides(const GroundTruth& gt,
                                const std::vector<std::pair<int, MapSurface>>& primary,
                                const SeamOptions& options = {});

}  // namespace pmap::eval
