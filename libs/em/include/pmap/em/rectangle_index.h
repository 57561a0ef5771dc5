// A hashed uniform grid over rectangles inflated by the E-step's cutoff
// distance: the surfaces that can matter for a point are those listed in its
// cell (every other surface is farther than the cutoff, so its term is below
// the responsibility tolerance; see MeasurementModel::cutoffDistance).
// Memory is bounded whatever the rectangles' extent: a rectangle spanning
// more than `max_cells` cells, and the largest ones once the index holds
// `max_total_cells` cell entries, are listed for every point instead.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "pmap/em/cell_key.h"
#include "pmap/em/surface.h"

namespace pmap::em {

class RectangleIndex {
 public:
  RectangleIndex() = default;
  /// Indexes `surfaces` inflated by `inflate_m`; unbounded planes,
  /// rectangles spanning more than `max_cells` cells and, beyond
  /// `max_total_cells` entries in all, the largest rectangles go to a global
  /// list.
  RectangleIndex(const std::vector<Surface>& surfaces, double inflate_m, double cell_m = 1.0,
                 std::size_t max_cells = 200000, std::size_t max_total_cells = 2000000);

  /// Candidate surface indices for a point (may contain far ones; never
  /// misses one within the inflation distance). Ascending.
  void candidates(const Eigen::Vector3d& p, std::vector<std::int32_t>& out) const;

  /// The same list without a copy when no surface is global (null: none);
  /// falls back to filling `scratch` otherwise.
  const std::vector<std::int32_t>* candidatesRef(const Eigen::Vector3d& p,
                                                 std::vector<std::int32_t>& scratch) const;

  /// Cell entries held (one per indexed surface and cell it spans).
  std::size_t indexedCells() const { return entries_; }
  /// Surfaces listed for every point.
  std::size_t globalCount() const { return global_.size(); }

 private:
  using Cell = Eigen::Matrix<std::int64_t, 3, 1>;
  Cell cellOf(const Eigen::Vector3d& p) const { return em::cellOf(p, cell_); }

  double cell_ = 1.0;
  std::unordered_map<std::int64_t, std::vector<std::int32_t>> cells_;
  std::vector<std::int32_t> global_;
  std::size_t entries_ = 0;
};

}  // namespace pmap::em
