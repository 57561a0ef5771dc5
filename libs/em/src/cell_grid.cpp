#include "pmap/em/cell_grid.h"

#include <algorithm>

#include "pmap/em/cell_key.h"

namespace pmap::em {

std::int32_t CellGrid::find(std::int64_t row, std::int64_t col) const {
  const GridCell c{row, col};
  const auto it = std::lower_bound(cells.begin(), cells.end(), c);
  return it != cells.end() && *it == c ? static_cast<std::int32_t>(it - cells.begin()) : -1;
}

namespace {

// Occupied cells and each member's index among them by a table over the
// grid: for grids at most a few times larger than the member count.
void indexDense(CellGrid& g, const std::vector<GridCell>& of_member) {
  std::vector<std::int32_t> id(static_cast<std::size_t>(g.cols * g.rows), -1);
  for (const GridCell& c : of_member) {
    id[static_cast<std::size_t>(c.row * g.cols + c.col)] = 0;
  }
  std::int32_t next = 0;
  for (std::size_t k = 0; k < id.size(); ++k) {
    if (id[k] == 0) {
      id[k] = next++;
      const auto at = static_cast<std::int64_t>(k);
      g.cells.push_back({at / g.cols, at % g.cols});
    }
  }
  for (const GridCell& c : of_member) {
    g.cell_of.push_back(id[static_cast<std::size_t>(c.row * g.cols + c.col)]);
  }
}

// The same by sorting the members' cells: memory follows the members
// whatever the grid's size.
void indexSparse(CellGrid& g, const std::vector<GridCell>& of_member) {
  g.cells = of_member;
  std::sort(g.cells.begin(), g.cells.end());
  g.cells.erase(std::unique(g.cells.begin(), g.cells.end()), g.cells.end());
  g.cells.shrink_to_fit();
  for (const GridCell& c : of_member) {
    g.cell_of.push_back(static_cast<std::int32_t>(
        std::lower_bound(g.cells.begin(), g.cells.end(), c) - g.cells.begin()));
  }
}

}  // namespace

CellGrid gridOf(const std::vector<Eigen::Vector3d>& points,
                const std::vector<std::int32_t>& members, const Rectangle& rect, double cell_m) {
  CellGrid g;
  g.cols = cellCount(2.0 * rect.half_u / cell_m);
  g.rows = cellCount(2.0 * rect.half_v / cell_m);
  const Eigen::Vector3d v = rect.axisV();
  std::vector<GridCell> of_member;
  of_member.reserve(members.size());
  for (const std::int32_t i : members) {
    const Eigen::Vector3d d = points[static_cast<std::size_t>(i)] - rect.centre;
    of_member.push_back({clampedCell((v.dot(d) + rect.half_v) / cell_m, g.rows),
                         clampedCell((rect.axis_u.dot(d) + rect.half_u) / cell_m, g.cols)});
  }
  g.cell_of.reserve(members.size());
  const double table = static_cast<double>(g.cols) * static_cast<double>(g.rows);
  if (table <= std::max(65536.0, 8.0 * static_cast<double>(members.size()))) {
    indexDense(g, of_member);
  } else {
    indexSparse(g, of_member);
  }
  return g;
}

SplitProposal partition(const std::vector<std::int32_t>& members,
                        const std::vector<std::int32_t>& cell_of, const std::vector<char>& in_a) {
  SplitProposal p;
  for (std::size_t k = 0; k < members.size(); ++k) {
    (in_a[static_cast<std::size_t>(cell_of[k])] ? p.part_a : p.part_b).push_back(members[k]);
  }
  return p;
}

}  // namespace pmap::em
