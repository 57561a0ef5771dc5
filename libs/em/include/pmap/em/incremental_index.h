// A hashed grid over rectangles that is updated surface by surface (the
// online EM changes a few surfaces per scan; rebuilding the whole index would
// cost time proportional to the map). Same query contract as RectangleIndex.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "pmap/em/rectangle.h"

namespace pmap::em {

class IncrementalIndex {
 public:
  IncrementalIndex(double inflate_m, double cell_m = 1.0) : inflate_(inflate_m), cell_(cell_m) {}

  /// Inserts or moves surface `j` (a stable slot number).
  void update(std::int32_t j, const Rectangle& rect);
  void remove(std::int32_t j);

  /// Candidate surfaces for a point: every surface within the inflation
  /// distance is listed (others may be). Ascending.
  void candidates(const Eigen::Vector3d& p, std::vector<std::int32_t>& out) const;

 private:
  std::int64_t key(int x, int y, int z) const;

  double inflate_;
  double cell_;
  std::unordered_map<std::int64_t, std::vector<std::int32_t>> cells_;
  std::unordered_map<std::int32_t, std::vector<std::int64_t>> keys_of_;
};

}  // namespace pmap::em
