// Parallel neighbours: a door recessed behind its wall keeps its own plane,
// and its edges are placed on the opening that the wall's points leave
// around it. The wall's rectangle covers the door (a rectangle has no
// holes), so the opening exists only in the wall's measurements: beside
// each edge of the door, the wall's nearest points. Each side of the edge is
// sampled (the door's last point, the wall's first point: one scan or one
// beam apart), so the edge is placed halfway between them, the maximum
// likelihood position of a boundary seen from both sides. Eq. (29)'s
// tight rectangle around the door's points alone is short of it by half a
// sample spacing on every side, and a door that also holds points of the
// reveal above it (the lintel's underside, within the outlier band of the
// door's plane) overshoots into the wall.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "pmap/em/surface.h"
#include "pmap/refine/refine_options.h"

namespace pmap::refine {

/// A door placed on its wall's opening.
struct Opening {
  std::int32_t door_id = -1;
  std::int32_t wall_id = -1;
  int edges = 0;          ///< door edges moved onto the opening (0..4)
  double max_move_m = 0;  ///< the largest edge move
};

struct OpeningResult {
  std::vector<Opening> openings;
};

/// Places the edges of every door (a surface parallel to a larger one, its
/// wall, within `opening_max_angle_deg`, behind the wall's plane as seen from
/// the wall's measurements by at most `seam_distance_m`, its centre inside
/// the wall's rectangle) on the opening in that wall's points. `assignment[i]` is the
/// index in `surfaces` of point i's most likely cause (-1: outlier);
/// `viewpoints[i]` the sensor origin of point i (empty: nothing is done, the
/// side a door is recessed to cannot be told). An edge moves only where the
/// wall has points beside it within `seam_distance_m`.
OpeningResult alignToOpenings(const std::vector<Eigen::Vector3d>& points,
                              const std::vector<std::int32_t>& assignment,
                              const std::vector<Eigen::Vector3d>& viewpoints,
                              const RefineOptions& options, std::vector<em::Surface>& surfaces);

}  // namespace pmap::refine
