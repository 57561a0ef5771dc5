#include "pmap/points/neighbour_graph.h"

#include <map>
#include <string>

namespace pmap::points {

NeighbourGraph neighbourGraph(const PointMap& map, double cloud_radius_m) {
  for (const ScanRecord& s : map.scans()) {
    if (!s.organised) {
      return {em::nearestNeighbours(map.xyz(), cloud_radius_m), {}};
    }
  }
  std::vector<em::GridKey> keys(map.size());
  std::map<std::string, std::pair<std::int32_t, std::int32_t>> sensors;  // label -> group, rank
  std::int32_t next_group = 0;
  for (const ScanRecord& s : map.scans()) {
    std::int32_t group = 0;
    std::int32_t rank = 0;
    if (s.rows > 1) {  // a range image: its own grid
      group = next_group++;
    } else {
      auto it = sensors.find(s.label);
      if (it == sensors.end()) {
        it = sensors.emplace(s.label, std::make_pair(next_group++, 0)).first;
      }
      group = it->second.first;
      rank = it->second.second++;
    }
    for (std::size_t k = 0; k < s.num_points; ++k) {
      const std::size_t p = s.first_point + k;
      const std::int32_t beam = map.beamIndex()[p];
      keys[p] = s.rows > 1 ? em::GridKey{group, beam / s.cols, beam % s.cols}
                           : em::GridKey{group, rank, beam};
    }
  }
  NeighbourGraph g;
  g.neighbours = em::gridNeighbours(keys);
  g.rows.reserve(keys.size());
  for (const em::GridKey& k : keys) {
    g.rows.push_back(k.row);
  }
  return g;
}

}  // namespace pmap::points
