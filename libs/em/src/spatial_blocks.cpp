#include "pmap/em/spatial_blocks.h"

#include <algorithm>
#include <limits>

namespace pmap::em {
namespace {

// The x-y box of points[index[first .. last)].
void boxOf(const std::vector<Eigen::Vector3d>& points, const std::vector<std::int32_t>& index,
           std::size_t first, std::size_t last, Eigen::Vector2d& lo, Eigen::Vector2d& hi) {
  lo.setConstant(std::numeric_limits<double>::infinity());
  hi = -lo;
  for (std::size_t k = first; k < last; ++k) {
    const Eigen::Vector2d p = points[static_cast<std::size_t>(index[k])].head<2>();
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
}

// Splits index[first .. last) at its median along the longer side of its
// box until each piece holds at most max_points; appends the pieces' own
// points (sorted back into input order) to `out`.
void split(const std::vector<Eigen::Vector3d>& points, std::vector<std::int32_t>& index,
           std::size_t first, std::size_t last, std::size_t max_points,
           std::vector<SpatialBlock>& out) {
  Eigen::Vector2d lo, hi;
  boxOf(points, index, first, last, lo, hi);
  if (last - first <= max_points) {
    SpatialBlock b;
    b.index.assign(index.begin() + static_cast<std::ptrdiff_t>(first),
                   index.begin() + static_cast<std::ptrdiff_t>(last));
    std::sort(b.index.begin(), b.index.end());
    b.core = b.index.size();
    b.lo = lo;
    b.hi = hi;
    out.push_back(std::move(b));
    return;
  }
  const int axis = hi.x() - lo.x() >= hi.y() - lo.y() ? 0 : 1;
  const std::size_t mid = first + (last - first) / 2;
  const auto by_axis = [&](std::int32_t a, std::int32_t b) {
    const double pa = points[static_cast<std::size_t>(a)](axis);
    const double pb = points[static_cast<std::size_t>(b)](axis);
    return pa < pb || (pa == pb && a < b);  // a strict total order: deterministic
  };
  std::nth_element(index.begin() + static_cast<std::ptrdiff_t>(first),
                   index.begin() + static_cast<std::ptrdiff_t>(mid),
                   index.begin() + static_cast<std::ptrdiff_t>(last), by_axis);
  split(points, index, first, mid, max_points, out);
  split(points, index, mid, last, max_points, out);
}

}  // namespace

std::size_t blockCount(std::size_t points, std::size_t max_points) {
  if (points <= max_points) {
    return 1;
  }
  const std::size_t half = points / 2;
  return blockCount(half, max_points) + blockCount(points - half, max_points);
}

std::vector<SpatialBlock> cutIntoBlocks(const std::vector<Eigen::Vector3d>& points,
                                        std::size_t max_points, double margin_m) {
  std::vector<SpatialBlock> out;
  if (points.empty()) {
    return out;
  }
  std::vector<std::int32_t> index(points.size());
  for (std::size_t i = 0; i < index.size(); ++i) {
    index[i] = static_cast<std::int32_t>(i);
  }
  split(points, index, 0, index.size(), std::max<std::size_t>(max_points, 1), out);
  if (out.size() < 2 || !(margin_m > 0.0)) {
    return out;
  }
  // Each point's block, then each block's margin: the others' points in its
  // grown box.
  std::vector<std::int32_t> owner(points.size());
  for (std::size_t b = 0; b < out.size(); ++b) {
    for (const std::int32_t i : out[b].index) {
      owner[static_cast<std::size_t>(i)] = static_cast<std::int32_t>(b);
    }
  }
  for (std::size_t b = 0; b < out.size(); ++b) {
    SpatialBlock& block = out[b];
    const Eigen::Vector2d lo = block.lo.array() - margin_m, hi = block.hi.array() + margin_m;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Eigen::Vector3d& p = points[i];
      if (owner[i] != static_cast<std::int32_t>(b) && p.x() >= lo.x() && p.x() <= hi.x() &&
          p.y() >= lo.y() && p.y() <= hi.y()) {
        block.index.push_back(static_cast<std::int32_t>(i));
      }
    }
  }
  return out;
}

BlockInput blockInput(const SpatialBlock& block, const std::vector<Eigen::Vector3d>& points,
                      const Neighbours& neighbours, const std::vector<std::int32_t>& rows) {
  BlockInput in;
  std::vector<std::int32_t> local(points.size(), -1);
  in.points.reserve(block.index.size());
  for (std::size_t k = 0; k < block.index.size(); ++k) {
    const auto i = static_cast<std::size_t>(block.index[k]);
    local[i] = static_cast<std::int32_t>(k);
    in.points.push_back(points[i]);
    if (!rows.empty()) {
      in.rows.push_back(rows[i]);
    }
  }
  in.neighbours.reserve(block.index.size());
  for (const std::int32_t i : block.index) {
    std::array<std::int32_t, 4> n = neighbours[static_cast<std::size_t>(i)];
    for (std::int32_t& j : n) {
      j = j < 0 ? -1 : local[static_cast<std::size_t>(j)];
    }
    in.neighbours.push_back(n);
  }
  return in;
}

}  // namespace pmap::em
