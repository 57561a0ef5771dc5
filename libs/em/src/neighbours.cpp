#include "pmap/em/neighbours.h"

#include <algorithm>
#include <cmath>
#include <thread>
#include <unordered_map>

#include "pmap/em/cell_key.h"

namespace pmap::em {
Neighbours gridNeighbours(const std::vector<GridKey>& keys) {
  std::unordered_map<GridKey, std::int32_t, GridKeyHash> index;
  index.reserve(keys.size());
  for (size_t i = 0; i < keys.size(); ++i) {
    index.emplace(keys[i], static_cast<std::int32_t>(i));
  }
  auto find = [&](std::int32_t g, std::int32_t r, std::int32_t c) -> std::int32_t {
    const auto it = index.find(GridKey{g, r, c});
    return it == index.end() ? -1 : it->second;
  };
  Neighbours out(keys.size());
  for (size_t i = 0; i < keys.size(); ++i) {
    const GridKey& k = keys[i];
    out[i] = {find(k.group, k.row, k.col - 1), find(k.group, k.row, k.col + 1),
              find(k.group, k.row - 1, k.col), find(k.group, k.row + 1, k.col)};
  }
  return out;
}

namespace {

// The four smallest (squared distance, index) pairs seen, ascending; an
// index seen twice (far cells hashed to one key, cell_key.h, or a point
// offered by both grids) counts once.
struct FourNearest {
  std::array<std::pair<double, std::int32_t>, 4> best;
  int count = 0;
  void offer(double d2, std::int32_t j) {
    const std::pair<double, std::int32_t> c(d2, j);
    if (count == 4 && !(c < best[3])) {
      return;
    }
    for (int m = 0; m < count; ++m) {
      if (best[static_cast<std::size_t>(m)].second == j) {
        return;
      }
    }
    int at = count < 4 ? count++ : 3;
    while (at > 0 && c < best[static_cast<std::size_t>(at - 1)]) {
      best[static_cast<std::size_t>(at)] = best[static_cast<std::size_t>(at - 1)];
      --at;
    }
    best[static_cast<std::size_t>(at)] = c;
  }
  bool full() const { return count == 4; }
  double worst() const { return best[3].first; }
};

// The points sorted by cell, each occupied cell a range of that order.
class CellIndex {
 public:
  CellIndex(const std::vector<Eigen::Vector3d>& points, double cell_m) : cell_(cell_m) {
    std::vector<std::pair<std::int64_t, std::int32_t>> keyed(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Eigen::Matrix<std::int64_t, 3, 1> c = cellOf(points[i], cell_);
      keyed[i] = {cellKey(c.x(), c.y(), c.z()), static_cast<std::int32_t>(i)};
    }
    std::sort(keyed.begin(), keyed.end());
    order_.resize(keyed.size());
    std::size_t cells = 0;
    for (std::size_t k = 0; k < keyed.size(); ++k) {
      cells += k == 0 || keyed[k].first != keyed[k - 1].first ? 1 : 0;
      order_[k] = keyed[k].second;
    }
    // Open addressing, linear probing, at most half full.
    std::size_t size = 16;
    while (size < 2 * cells) {
      size *= 2;
    }
    mask_ = size - 1;
    slots_.assign(size, Slot{});
    for (std::size_t k = 0; k < keyed.size();) {
      std::size_t e = k;
      while (e < keyed.size() && keyed[e].first == keyed[k].first) {
        ++e;
      }
      std::size_t h = slotOf(keyed[k].first);
      while (slots_[h].end != 0) {
        h = (h + 1) & mask_;
      }
      slots_[h] = {keyed[k].first, static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(e)};
      k = e;
    }
  }

  // Scans the rings of cells around p's, nearest first, up to ring `last`
  // (ring k: the cells whose largest offset from p's cell is k),
  // offering the points within sqrt(r2) of p other than `self`; stops after
  // a ring once the fourth nearest is closer than any point not yet scanned.
  // Returns whether it stopped so (the answer is final).
  bool scanRings(const std::vector<Eigen::Vector3d>& points, std::size_t self, double r2,
                 std::int64_t last, FourNearest& near) const {
    const Eigen::Vector3d& p = points[self];
    const Eigen::Matrix<std::int64_t, 3, 1> c = cellOf(p, cell_);
    const Eigen::Vector3d f = p / cell_ - c.cast<double>();  // in [0, 1] up to rounding
    const auto scan = [&](std::int64_t dx, std::int64_t dy, std::int64_t dz) {
      const Eigen::Vector3d lo(static_cast<double>(dx), static_cast<double>(dy),
                               static_cast<double>(dz));
      const double gap2 =
          (lo - f).cwiseMax(f - (lo.array() + 1.0).matrix()).cwiseMax(0.0).squaredNorm() * cell_ *
          cell_;
      if (gap2 > r2 || (near.full() && gap2 > near.worst())) {
        return;  // nothing in that cell can be a neighbour
      }
      const Slot* cell = find(cellKey(c.x() + dx, c.y() + dy, c.z() + dz));
      if (cell == nullptr) {
        return;
      }
      for (std::size_t k = cell->begin; k < cell->end; ++k) {
        const std::int32_t j = order_[k];
        const double d2 = (points[static_cast<std::size_t>(j)] - p).squaredNorm();
        if (static_cast<std::size_t>(j) != self && d2 <= r2) {
          near.offer(d2, j);
        }
      }
    };
    for (std::int64_t k = 0; k <= last; ++k) {
      for (std::int64_t dx = -k; dx <= k; ++dx) {
        for (std::int64_t dy = -k; dy <= k; ++dy) {
          const bool side = dx == -k || dx == k || dy == -k || dy == k;
          for (std::int64_t dz = -k; dz <= k; dz += side ? 1 : 2 * k) {
            scan(dx, dy, dz);
          }
        }
      }
      // Every point within `covered` of p is in the (2k + 1)^3 cells around c.
      const double kd = static_cast<double>(k);
      const double covered =
          std::max(0.0, std::min((f.array() + kd).minCoeff(), (kd + 1.0 - f.array()).minCoeff())) *
          cell_;
      if (covered * covered >= r2 || (near.full() && near.worst() <= covered * covered)) {
        return true;
      }
    }
    return false;
  }

  /// The points in cell order (neighbouring queries touch the same memory).
  std::int32_t pointAt(std::size_t k) const { return order_[k]; }

 private:
  struct Slot {
    std::int64_t key = 0;
    std::uint32_t begin = 0, end = 0;  ///< its points: order_[begin, end); end 0: empty slot
  };
  std::size_t slotOf(std::int64_t key) const {
    return static_cast<std::size_t>((static_cast<std::uint64_t>(key) * 0x9E3779B97F4A7C15ull) >>
                                    32) &
           mask_;
  }
  const Slot* find(std::int64_t key) const {
    for (std::size_t h = slotOf(key);; h = (h + 1) & mask_) {
      const Slot& s = slots_[h];
      if (s.end == 0) {
        return nullptr;
      }
      if (s.key == key) {
        return &s;
      }
    }
  }

  double cell_;
  std::vector<std::int32_t> order_;  ///< the points in cell order
  std::vector<Slot> slots_;
  std::size_t mask_ = 0;
};

}  // namespace

// The fine grid's cell: about four times the typical distance to the fourth
// nearest point (the median over up to 1,000 points spread through the
// input, found exactly on the coarse grid), between an eighth and half of
// the radius. Cells that hold a few points each keep the number of cells
// looked up per point small: on a range camera's frame (fourth nearest 4-5
// mm) that is an eighth of 0.15 m, on a 2D laser's sweep through a building
// (2-3 cm) half of it: on doc/cloud-scaling.md's 5M-point cloud 3.6 s
// instead of 17 s with an eighth. The answer does not depend on it.
double fineCell(const std::vector<Eigen::Vector3d>& points, const CellIndex& coarse, double r2,
                double radius_m) {
  constexpr std::size_t kSamples = 1000;
  const std::size_t n = points.size();
  const std::size_t m = std::min(n, kSamples);
  std::vector<double> fourth;
  for (std::size_t s = 0; s < m; ++s) {
    const std::size_t i = s * n / m;
    FourNearest near;
    coarse.scanRings(points, i, r2, 1, near);
    if (near.full()) {
      fourth.push_back(std::sqrt(near.worst()));
    }
  }
  if (fourth.empty() || 2 * fourth.size() < m) {  // mostly sparse: the coarse grid answers
    return 0.5 * radius_m;
  }
  std::nth_element(fourth.begin(), fourth.begin() + fourth.size() / 2, fourth.end());
  return std::clamp(4.0 * fourth[fourth.size() / 2], 0.125 * radius_m, 0.5 * radius_m);
}

// Two grids: a fine one (fineCell), where a point's four nearest are found
// in the first rings, and the radius itself, whose 27 cells around a point
// hold everything within the radius, for sparse points. Each point scans
// the fine grid's rings 0-2 nearest first, stopping once its fourth nearest
// is closer than every point not yet scanned, else the coarse grid's 27
// cells. Exactly the four nearest within the radius, ties by index.
Neighbours nearestNeighbours(const std::vector<Eigen::Vector3d>& points, double radius_m,
                             int threads) {
  Neighbours out(points.size(), {-1, -1, -1, -1});
  const double r2 = radius_m * radius_m;
  const CellIndex coarse(points, radius_m);
  const CellIndex fine(points, fineCell(points, coarse, r2, radius_m));
  // Each thread answers one stretch of the cell order: disjoint outputs.
  const auto answer = [&](std::size_t first, std::size_t last) {
    for (std::size_t k = first; k < last; ++k) {
      const auto i = static_cast<std::size_t>(fine.pointAt(k));
      FourNearest near;
      if (!fine.scanRings(points, i, r2, 2, near)) {
        coarse.scanRings(points, i, r2, 1, near);
      }
      for (int m = 0; m < near.count; ++m) {
        out[i][static_cast<std::size_t>(m)] = near.best[static_cast<std::size_t>(m)].second;
      }
    }
  };
  const std::size_t n = points.size();
  const auto parts = static_cast<std::size_t>(std::clamp(threads, 1, 256));
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < parts; ++t) {
    pool.emplace_back(answer, n * t / parts, n * (t + 1) / parts);
  }
  answer(0, n / parts);
  for (std::thread& t : pool) {
    t.join();
  }
  return out;
}

}  // namespace pmap::em
