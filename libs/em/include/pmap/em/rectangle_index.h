// A hashed uniform grid over rectangles inflated by the E-step's cutoff
// distance: the surfaces that can matter for a point are those listed in its
// cell (every other surface is farther than the cutoff, so its term is below
// the responsibility tolerance; see MeasurementModel::cutoffDistance).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "pmap/em/surface.h"

namespace pmap::em {

class RectangleIndex {
 public:
  RectangleIndex() = default;
  /// Indexes `surfaces` inflated by `inflate_m`; unbounded planes and
  /// rectangles spanning more than `max_cells` cells go to a global list.
  RectangleIndex(const std::vector<Surface>& surfaces, double inflate_m, double cell_m = 1.0,
                 std::size_t max_cells = 200000);

  /// Candidate surface indices for a point (may contain far ones; never
  /// misses one within the inflation distance). Ascending.
  void candidates(const Eigen::Vector3d& p, std::vector<std::int32_t>& out) const;

  /// The same list without a copy when no surface is global (null: none);
  /// falls back to filling `scratch` otherwise.
  const std::vector<std::int32_t>* candidatesRef(const Eigen::Vector3d& p,
                                                 std::vector<std::int32_t>& scratch) const;

 private:
  std::int64_t key(const Eigen::Vector3i& c) const;
  Eigen::Vector3i cellOf(const Eigen::Vector3d& p) const;

  double cell_ = 1.0;
  std::unordered_map<std::int64_t, std::vector<std::int32_t>> cells_;
  std::vector<std::int32_t> global_;
};

}  // namespace pmap::em
