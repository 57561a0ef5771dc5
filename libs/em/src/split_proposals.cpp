#include "pmap/em/split_proposals.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "pmap/em/cell_grid.h"

namespace pmap::em {
namespace {

// 4-connected components of flagged occupied cells with the same sign;
// returns the component id per occupied cell (-1 unflagged) and the number of
// components. Ids follow the row-major order of each component's first cell.
int components(const CellGrid& g, const std::vector<int>& sign, std::vector<int>& comp) {
  comp.assign(sign.size(), -1);
  int count = 0;
  std::vector<std::int32_t> stack;
  for (std::size_t start = 0; start < sign.size(); ++start) {
    if (sign[start] == 0 || comp[start] >= 0) {
      continue;
    }
    comp[start] = count;
    stack = {static_cast<std::int32_t>(start)};
    while (!stack.empty()) {
      const auto c = static_cast<std::size_t>(stack.back());
      stack.pop_back();
      const GridCell& at = g.cells[c];
      const GridCell nbr[4] = {
          {at.row - 1, at.col}, {at.row + 1, at.col}, {at.row, at.col - 1}, {at.row, at.col + 1}};
      for (const GridCell& n : nbr) {
        const std::int32_t m = g.find(n.row, n.col);
        if (m >= 0 && sign[static_cast<std::size_t>(m)] == sign[c] &&
            comp[static_cast<std::size_t>(m)] < 0) {
          comp[static_cast<std::size_t>(m)] = count;
          stack.push_back(m);
        }
      }
    }
    ++count;
  }
  return count;
}

}  // namespace

std::vector<SplitProposal> residualSplits(const std::vector<Eigen::Vector3d>& points,
                                          const std::vector<std::int32_t>& members,
                                          const Rectangle& rect, double cell_m, double min_offset_m,
                                          double sigma, std::size_t min_part,
                                          const SelectionRules& rules) {
  std::vector<SplitProposal> out;
  if (members.size() < 2 * min_part) {
    return out;
  }
  // Cells large enough to hold ~residual_cell_points points on average: a
  // patch's mean residual is then known to ~sigma/5, and noise-thinned
  // patches still count.
  const double density = static_cast<double>(members.size()) / std::max(rect.area(), 1e-9);
  cell_m = std::max(cell_m, std::sqrt(rules.residual_cell_points / density));
  const CellGrid g = gridOf(points, members, rect, cell_m);
  const std::size_t cells = g.cells.size();  // occupied cells only
  std::vector<double> sum(cells, 0.0);
  std::vector<int> count(cells, 0);
  for (std::size_t k = 0; k < members.size(); ++k) {
    const auto c = static_cast<std::size_t>(g.cell_of[k]);
    sum[c] += rect.planeDistance(points[static_cast<std::size_t>(members[k])]);
    ++count[c];
  }
  std::vector<int> sign(cells, 0);
  for (std::size_t c = 0; c < cells; ++c) {
    if (count[c] < rules.residual_min_cell_points) {
      continue;
    }
    const double mean = sum[c] / count[c];
    if (std::abs(mean) > min_offset_m &&
        std::abs(mean) > rules.residual_sigmas * sigma / std::sqrt(count[c])) {
      sign[c] = mean > 0 ? 1 : -1;
    }
  }
  std::vector<int> comp;
  const int n = components(g, sign, comp);
  std::vector<std::pair<std::size_t, int>> by_size;  // points, component
  for (int k = 0; k < n; ++k) {
    by_size.emplace_back(0, k);
  }
  for (std::size_t c = 0; c < cells; ++c) {
    if (comp[c] >= 0) {
      by_size[static_cast<std::size_t>(comp[c])].first += static_cast<std::size_t>(count[c]);
    }
  }
  std::sort(by_size.begin(), by_size.end(), [](const auto& a, const auto& b) {
    return a.first > b.first || (a.first == b.first && a.second < b.second);
  });
  std::vector<char> in_a(cells, 0);
  for (const auto& [size, k] : by_size) {
    for (std::size_t c = 0; c < cells; ++c) {
      in_a[c] = comp[c] == k ? 1 : 0;
    }
    SplitProposal p = partition(members, g.cell_of, in_a);
    if (p.part_a.size() >= min_part && p.part_b.size() >= min_part) {
      out.push_back(std::move(p));
    }
  }
  return out;
}

std::optional<SplitProposal> residualSplit(const std::vector<Eigen::Vector3d>& points,
                                           const std::vector<std::int32_t>& members,
                                           const Rectangle& rect, double cell_m,
                                           double min_offset_m, double sigma, std::size_t min_part,
                                           const SelectionRules& rules) {
  std::vector<SplitProposal> all =
      residualSplits(points, members, rect, cell_m, min_offset_m, sigma, min_part, rules);
  if (all.empty()) {
    return std::nullopt;
  }
  return std::move(all.front());
}

}  // namespace pmap::em
