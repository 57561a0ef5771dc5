// The grid over a surface's rectangle that the split tests share
// (split_proposals.cpp, coverage_cut.cpp): each member's cell, and the
// partition of the members by a set of cells.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "pmap/em/rectangle.h"
#include "pmap/em/split_proposals.h"

namespace pmap::em::detail {

struct CellGrid {
  int cols = 0;
  int rows = 0;
  std::vector<int> cell_of;  // per member
};

inline CellGrid gridOf(const std::vector<Eigen::Vector3d>& points,
                       const std::vector<std::int32_t>& members, const Rectangle& rect,
                       double cell_m) {
  CellGrid g;
  g.cols = std::max(1, static_cast<int>(std::ceil(2.0 * rect.half_u / cell_m)));
  g.rows = std::max(1, static_cast<int>(std::ceil(2.0 * rect.half_v / cell_m)));
  const Eigen::Vector3d v = rect.axisV();
  for (const std::int32_t i : members) {
    const Eigen::Vector3d d = points[static_cast<std::size_t>(i)] - rect.centre;
    const int c =
        std::clamp(static_cast<int>((rect.axis_u.dot(d) + rect.half_u) / cell_m), 0, g.cols - 1);
    const int r = std::clamp(static_cast<int>((v.dot(d) + rect.half_v) / cell_m), 0, g.rows - 1);
    g.cell_of.push_back(r * g.cols + c);
  }
  return g;
}

inline SplitProposal partition(const std::vector<std::int32_t>& members,
                               const std::vector<int>& cell_of, const std::vector<char>& in_a) {
  SplitProposal p;
  for (std::size_t k = 0; k < members.size(); ++k) {
    (in_a[static_cast<std::size_t>(cell_of[k])] ? p.part_a : p.part_b).push_back(members[k]);
  }
  return p;
}

}  // namespace pmap::em::detail
