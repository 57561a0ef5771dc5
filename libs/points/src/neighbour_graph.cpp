#include "pmap/points/neighbour_graph.h"

#include "pmap/points/grid_keys.h"

namespace pmap::points {

NeighbourGraph neighbourGraph(const PointMap& map, double cloud_radius_m, int threads) {
  for (const ScanRecord& s : map.scans()) {
    if (!s.organised) {
      return {em::nearestNeighbours(map.xyz(), cloud_radius_m, threads), {}};
    }
  }
  std::vector<em::GridKey> keys;
  keys.reserve(map.size());
  GridKeyer keyer;
  for (const ScanRecord& s : map.scans()) {
    const std::vector<em::GridKey> k = keyer.keysOf(map, s);
    keys.insert(keys.end(), k.begin(), k.end());
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
