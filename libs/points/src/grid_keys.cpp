#include "pmap/points/grid_keys.h"

namespace pmap::points {

std::vector<em::GridKey> GridKeyer::keysOf(const PointMap& map, const ScanRecord& s) {
  std::int32_t group = 0;
  std::int32_t rank = 0;
  if (s.rows > 1) {  // a range image: its own grid
    group = next_group_++;
  } else {
    auto it = sensors_.find(s.label);
    if (it == sensors_.end()) {
      it = sensors_.emplace(s.label, std::make_pair(next_group_++, 0)).first;
    }
    group = it->second.first;
    rank = it->second.second++;
  }
  std::vector<em::GridKey> keys;
  keys.reserve(s.num_points);
  for (std::size_t k = 0; k < s.num_points; ++k) {
    const std::int32_t beam = map.beamIndex()[s.first_point + k];
    keys.push_back(s.rows > 1 ? em::GridKey{group, beam / s.cols, beam % s.cols}
                              : em::GridKey{group, rank, beam});
  }
  return keys;
}

}  // namespace pmap::points
