// Where surfaces meet: a seam is an edge of one rectangle that lies near a
// non-parallel surface's plane, runs along the two planes' intersection line
// and is next to that surface's rectangle (a wall's top edge under the
// ceiling, a wall's end at a corner or a junction). The refinement makes the
// edge end on the line.
#pragma once

#include <cstddef>
#include <vector>

#include "pmap/refine/refine_options.h"
#include "pmap/refine/surface_params.h"

namespace pmap::refine {

struct Seam {
  std::size_t surface = 0;  ///< whose edge ends on the line
  int edge = 0;             ///< 0..3 (surface_params.h)
  std::size_t other = 0;    ///< the surface whose plane it ends on
  /// The part of the edge beside the other rectangle, as two in-plane
  /// coordinates along the edge (s for edges 0 and 2, t for 1 and 3, in the
  /// frame of surface_params.h): the seam is held at these two points, not
  /// at the edge's far corners (a long wall under a short ceiling piece).
  std::array<double, 2> along{0, 0};
  double distance_m = 0;  ///< mean in-plane distance of those points to the line, before
};

/// The seams of `surfaces` (indices into it), ordered by (surface, edge,
/// other). An edge may end on several planes along its length (a wall's top
/// edge under two ceiling pieces). Parallel surfaces never form a seam.
std::vector<Seam> findSeams(const std::vector<SurfaceParams>& surfaces,
                            const RefineOptions& options);

/// In-plane distance from `point` (on plane a) to the line where planes a
/// and b meet: |n_b . p - d_b| / sin(angle between the normals). Infinite for
/// parallel planes.
double distanceToIntersection(const Eigen::Vector3d& n_a, const Eigen::Vector3d& n_b,
                              double offset_b, const Eigen::Vector3d& point);

}  // namespace pmap::refine
