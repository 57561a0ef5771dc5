// Each measurement's place in a grid (em::GridKey): for a 2D scanner,
// group = the sensor, row = the scan's rank among that sensor's placed scans,
// col = the beam; a range image is a grid of its own (row, col = pixel).
// Used for neighbours in the offline EM and, scan by scan, the online EM.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "pmap/em/neighbours.h"
#include "pmap/points/point_map.h"

namespace pmap::points {

class GridKeyer {
 public:
  /// Keys of the points of `scan` (a record of `map`), in point order.
  std::vector<em::GridKey> keysOf(const PointMap& map, const ScanRecord& scan);

 private:
  std::map<std::string, std::pair<std::int32_t, std::int32_t>> sensors_;  // label -> group, rank
  std::int32_t next_group_ = 0;
};

}  // namespace pmap::points
