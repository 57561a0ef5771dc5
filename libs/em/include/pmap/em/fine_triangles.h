// Measurements whose most likely cause is the outlier class are kept as fine
// polygons (section IV, "fine-grained polygons"): every three nearby ones
// give one small triangle, each point used once, each triangle proper (not a
// sliver) with edges <= `max_edge_m`.
//
// cell_m = 0, the paper's method: every outlier is a vertex candidate; points
// are grouped greedily in index (scan) order, each with its two closest
// unused outlier neighbours (one or two hops in the neighbour graph).
//
// cell_m > 0 (beyond the paper): the outliers are first thinned to one per
// cube of side cell_m, the one nearest the mean of the cube's outliers, and
// those are grouped greedily in cube order with their closest unused
// neighbours in space. Clutter seen by many scans (a lamp under every pass of
// the vertical laser) then costs triangles in proportion to its size, not to
// the number of times it was seen.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <vector>

#include "pmap/em/neighbours.h"

namespace pmap::em {

using Triangle = std::array<std::int32_t, 3>;

std::vector<Triangle> fineTriangles(const std::vector<Eigen::Vector3d>& points,
                                    const Neighbours& neighbours,
                                    const std::vector<char>& is_outlier, double max_edge_m,
                                    double cell_m = 0.0);

/// The points standing for the outliers when they are thinned to one per cube
/// of side `cell_m` (> 0): in each cube holding outliers, the outlier nearest
/// their mean (the lowest index on a tie). Indices into `points`, in the
/// cubes' (x, y, z) lexicographic order.
std::vector<std::int32_t> cubeRepresentatives(const std::vector<Eigen::Vector3d>& points,
                                              const std::vector<char>& is_outlier, double cell_m);

}  // namespace pmap::em
