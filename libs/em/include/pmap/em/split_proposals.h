// Beyond the paper: tests that propose splitting one surface in two.
//  - Residual patches: a door recessed less than the outlier distance
//    (MODEL.md) stays "explained" by its wall, so the paper's seeding never
//    separates it; but on a grid over the wall the door's cells share a mean
//    residual clearly off the wall plane. Those cells, if connected, form one
//    part.
//  - Coverage cuts: coverage_cut.h.
// A proposal is only a partition; the selector fits both parts and keeps the
// split when it raises the log posterior.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "pmap/em/rectangle.h"
#include "pmap/em/selection_rules.h"

namespace pmap::em {

struct SplitProposal {
  std::vector<std::int32_t> part_a;
  std::vector<std::int32_t> part_b;
};

/// Residual-patch splits of `members` (the surface's hard points): one
/// proposal per connected group of off-plane cells, largest first. The cell
/// and off-plane tests: rules.residual_* (selection_rules.h).
std::vector<SplitProposal> residualSplits(const std::vector<Eigen::Vector3d>& points,
                                          const std::vector<std::int32_t>& members,
                                          const Rectangle& rect, double cell_m, double min_offset_m,
                                          double sigma, std::size_t min_part,
                                          const SelectionRules& rules = SelectionRules{});

/// The largest of residualSplits, if any.
std::optional<SplitProposal> residualSplit(const std::vector<Eigen::Vector3d>& points,
                                           const std::vector<std::int32_t>& members,
                                           const Rectangle& rect, double cell_m,
                                           double min_offset_m, double sigma, std::size_t min_part,
                                           const SelectionRules& rules = SelectionRules{});

}  // namespace pmap::em
