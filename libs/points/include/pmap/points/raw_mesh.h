// The raw polygon map the paper compares against (its Fig. 3/4a, "nearby
// measurements of neighbouring scans joined into polygons").
//
// Rule (doc/outputs.md): for two consecutive scans of the same 2D structure
// sensor, s and s+1, and neighbouring beams i and i+1, the quad
// (s,i) (s,i+1) (s+1,i+1) (s+1,i) becomes two triangles when all four points
// are valid and each of its four sides is at most `max_edge_m` long; the quad
// is split along its shorter diagonal. Range images (3D frames) use the same
// rule on neighbouring pixels of one frame. Unorganised clouds (Velodyne,
// point clouds, PLY input) give no raw triangles.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "pmap/points/point_map.h"

namespace pmap::points {

struct RawMeshOptions {
  double max_edge_m = 0.3;  ///< longest side of a kept quad (m)
  bool validate(std::string* why) const;
};

class RawMeshBuilder {
 public:
  explicit RawMeshBuilder(RawMeshOptions options = {}) : options_(options) {}

  /// Adds the triangles that scan `scan_record` (just added to `map`) forms
  /// with the previous scan of the same sensor, or within itself for a range
  /// image of `rows` x `cols`.
  void addScan(const PointMap& map, std::size_t scan_record, int rows, int cols, bool organised);

  /// Triangles as indices into the PointMap.
  const std::vector<std::array<std::uint32_t, 3>>& triangles() const { return triangles_; }

 private:
  struct Grid {
    int cols = 0;
    std::vector<std::int64_t> point_of_beam;  // -1 where no valid point
  };
  Grid makeGrid(const PointMap& map, const ScanRecord& scan, int rows, int cols) const;
  void addQuad(const PointMap& map, std::int64_t a, std::int64_t b, std::int64_t c, std::int64_t d);

  RawMeshOptions options_;
  std::map<std::string, Grid> previous_;  // last 2D scan of each sensor label
  std::vector<std::array<std::uint32_t, 3>> triangles_;
};

}  // namespace pmap::points
