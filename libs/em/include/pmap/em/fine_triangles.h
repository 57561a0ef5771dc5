// Measurements whose most likely cause is the outlier class are kept as fine
// polygons (section IV, "fine-grained polygons"): every three nearby ones
// give one small triangle. Points are grouped greedily in index (scan) order,
// each with its two closest unused outlier neighbours (one or two hops in the
// neighbour graph) within `max_edge_m`; each point is used once.
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
                                    const std::vector<char>& is_outlier, double max_edge_m);

}  // namespace pmap::em
