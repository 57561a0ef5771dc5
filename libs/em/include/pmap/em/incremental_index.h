// A hashed grid over rectangles that is updated surface by surface (the
// online EM changes a few surfaces per scan; rebuilding the whole index would
// cost time proportional to the map). Same query contract as RectangleIndex,
// and the same memory bound: a rectangle spanning more than `max_cells`
// cells, or one that would take the index beyond `max_total_cells` cell
// entries, is listed for every point instead of rasterised.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "pmap/em/cell_key.h"
#include "pmap/em/rectangle.h"

namespace pmap::em {

class IncrementalIndex {
 public:
  IncrementalIndex(double inflate_m, double cell_m = 1.0, std::size_t max_cells = 200000,
                   std::size_t max_total_cells = 2000000)
      : inflate_(inflate_m),
        cell_(cell_m),
        max_cells_(max_cells),
        max_total_cells_(max_total_cells) {}

  /// Inserts or moves surface `j` (a stable slot number).
  void update(std::int32_t j, const Rectangle& rect);
  void remove(std::int32_t j);

  /// Candidate surfaces for a point: every surface within the inflation
  /// distance is listed (others may be). Ascending.
  void candidates(const Eigen::Vector3d& p, std::vector<std::int32_t>& out) const;

  /// Cell entries held (one per rasterised surface and cell it spans).
  std::size_t indexedCells() const { return entries_; }
  /// Surfaces listed for every point.
  std::size_t globalCount() const { return global_.size(); }

 private:
  using Cell = Eigen::Matrix<std::int64_t, 3, 1>;
  Cell cellOf(const Eigen::Vector3d& p) const { return em::cellOf(p, cell_); }

  double inflate_;
  double cell_;
  std::size_t max_cells_;
  std::size_t max_total_cells_;
  std::size_t entries_ = 0;
  std::unordered_map<std::int64_t, std::vector<std::int32_t>> cells_;
  std::unordered_map<std::int32_t, std::vector<std::int64_t>> keys_of_;
  std::vector<std::int32_t> global_;  ///< ascending
};

}  // namespace pmap::em
