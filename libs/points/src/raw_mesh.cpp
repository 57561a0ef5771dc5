#include "pmap/points/raw_mesh.h"

#include <cmath>

namespace pmap::points {

bool RawMeshOptions::validate(std::string* why) const {
  if (!(max_edge_m > 0.0) || !std::isfinite(max_edge_m)) {
    *why = "raw_max_edge_m must be a positive number of metres";
    return false;
  }
  return true;
}

RawMeshBuilder::Grid RawMeshBuilder::makeGrid(const PointMap& map, const ScanRecord& scan, int rows,
                                              int cols) const {
  Grid g;
  g.cols = cols;
  g.point_of_beam.assign(static_cast<size_t>(rows) * static_cast<size_t>(cols), -1);
  for (size_t k = 0; k < scan.num_points; ++k) {
    const size_t p = scan.first_point + k;
    const auto beam = static_cast<size_t>(map.beamIndex()[p]);
    if (beam < g.point_of_beam.size()) {
      g.point_of_beam[beam] = static_cast<std::int64_t>(p);
    }
  }
  return g;
}

// Quad a-b-c-d in order around its boundary.
void RawMeshBuilder::addQuad(const PointMap& map, std::int64_t a, std::int64_t b, std::int64_t c,
                             std::int64_t d) {
  if (a < 0 || b < 0 || c < 0 || d < 0) {
    return;
  }
  const auto& x = map.xyz();
  const double max2 = options_.max_edge_m * options_.max_edge_m;
  const std::int64_t q[4] = {a, b, c, d};
  for (int i = 0; i < 4; ++i) {
    if ((x[q[i]] - x[q[(i + 1) % 4]]).squaredNorm() > max2) {
      return;
    }
  }
  auto u = [](std::int64_t i) { return static_cast<std::uint32_t>(i); };
  if ((x[a] - x[c]).squaredNorm() <= (x[b] - x[d]).squaredNorm()) {
    triangles_.push_back({u(a), u(b), u(c)});
    triangles_.push_back({u(a), u(c), u(d)});
  } else {
    triangles_.push_back({u(a), u(b), u(d)});
    triangles_.push_back({u(b), u(c), u(d)});
  }
}

void RawMeshBuilder::addScan(const PointMap& map, std::size_t scan_record, int rows, int cols,
                             bool organised) {
  if (!organised || cols < 2) {
    return;
  }
  const ScanRecord& scan = map.scans()[scan_record];
  Grid grid = makeGrid(map, scan, rows, cols);
  if (rows > 1) {  // range image: neighbouring pixels of one frame
    for (int r = 0; r + 1 < rows; ++r) {
      for (int c = 0; c + 1 < cols; ++c) {
        const auto& g = grid.point_of_beam;
        const size_t i = static_cast<size_t>(r) * cols + c;
        addQuad(map, g[i], g[i + 1], g[i + cols + 1], g[i + cols]);
      }
    }
    return;
  }
  auto prev = previous_.find(scan.label);
  if (prev != previous_.end() && prev->second.cols == cols) {
    const auto& g0 = prev->second.point_of_beam;
    const auto& g1 = grid.point_of_beam;
    for (int i = 0; i + 1 < cols; ++i) {
      addQuad(map, g0[i], g0[i + 1], g1[i + 1], g1[i]);
    }
  }
  previous_[scan.label] = std::move(grid);
}

}  // namespace pmap::points
