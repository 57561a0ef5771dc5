// Which measurements of a PointMap are adjacent (for EM seeding and fine
// triangles): neighbouring beams and the same beam in the previous / next
// scan of the same 2D sensor; neighbouring pixels of a range image; nearest
// neighbours within `cloud_radius_m` when any scan is an unorganised cloud.
#pragma once

#include "pmap/em/neighbours.h"
#include "pmap/points/point_map.h"

namespace pmap::points {

struct NeighbourGraph {
  em::Neighbours neighbours;
  /// Per point its row: the scan's rank among its sensor's scans, or the
  /// pixel row of a range image; empty for clouds.
  std::vector<std::int32_t> rows;
};

NeighbourGraph neighbourGraph(const PointMap& map, double cloud_radius_m, int threads = 1);

}  // namespace pmap::points
