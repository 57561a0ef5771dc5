// The grid over a surface's rectangle that the split tests share
// (split_proposals.cpp, coverage_cut.cpp): each member's cell, and the
// partition of the members by a set of cells. Sparse: only the occupied
// cells are stored, so its memory follows the members, not the rectangle's
// extent (a rectangle stretched over 1e9 m by a stray point costs no more
// than a room's).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "pmap/em/rectangle.h"
#include "pmap/em/split_proposals.h"

namespace pmap::em {

/// One cell of a CellGrid: row along axis_v, column along axis_u.
struct GridCell {
  std::int64_t row = 0;
  std::int64_t col = 0;
  bool operator<(const GridCell& o) const { return row < o.row || (row == o.row && col < o.col); }
  bool operator==(const GridCell& o) const { return row == o.row && col == o.col; }
};

struct CellGrid {
  std::int64_t cols = 0;              ///< cells along axis_u over the rectangle
  std::int64_t rows = 0;              ///< cells along axis_v
  std::vector<GridCell> cells;        ///< the occupied cells, row-major ascending
  std::vector<std::int32_t> cell_of;  ///< per member: its index in `cells`

  /// Index in `cells` of cell (row, col); -1 when it holds no member.
  std::int32_t find(std::int64_t row, std::int64_t col) const;
};

/// The members' cells on a grid of `cell_m` over `rect` (members beyond the
/// rectangle count in its border cells).
CellGrid gridOf(const std::vector<Eigen::Vector3d>& points,
                const std::vector<std::int32_t>& members, const Rectangle& rect, double cell_m);

/// Members in cells flagged in `in_a` (one flag per occupied cell) go to
/// part_a, the others to part_b, in member order.
SplitProposal partition(const std::vector<std::int32_t>& members,
                        const std::vector<std::int32_t>& cell_of, const std::vector<char>& in_a);

}  // namespace pmap::em
