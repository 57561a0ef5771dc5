#include "pmap/poses/pooled_grid.h"

#include <algorithm>

namespace pmap::poses {

PooledGrid::PooledGrid(int cols, int rows)
    : cols_(cols),
      rows_(rows),
      tile_cols_((cols + kMask) >> kBits),
      tile_rows_((rows + kMask) >> kBits) {
  levels_.resize(1);
  levels_[0].index.assign(static_cast<std::size_t>(tile_cols_) * tile_rows_, -1);
}

void PooledGrid::raiseRow(int c, int r, const float* values, int n) {
  Level& level = levels_[0];
  const std::size_t row = static_cast<std::size_t>((r >> kBits) * tile_cols_);
  const std::size_t in_row = static_cast<std::size_t>((r & kMask) << kBits);
  while (n > 0) {
    std::int32_t& t = level.index[row + static_cast<std::size_t>(c >> kBits)];
    if (t < 0) {
      t = static_cast<std::int32_t>(level.cells.size() / kCells);
      level.cells.resize(level.cells.size() + kCells, 0.0f);
    }
    // The run's cells in this tile are contiguous: its row within the tile.
    float* cells = &level.cells[static_cast<std::size_t>(t) * kCells + in_row];
    const int here = std::min(n, kSide - (c & kMask));
    for (int k = 0; k < here; ++k) {
      float& cell = cells[(c + k) & kMask];
      cell = std::max(cell, values[k]);
    }
    c += here;
    values += here;
    n -= here;
  }
}

std::int32_t PooledGrid::tileIndex(const Level& level, int tc, int tr) const {
  if (tc >= tile_cols_ || tr >= tile_rows_) {
    return -1;
  }
  return level.index[static_cast<std::size_t>(tr * tile_cols_ + tc)];
}

void PooledGrid::pool(int count) {
  while (levels() < count && !empty()) {
    addLevel();
  }
}

const float* PooledGrid::tile(const Level& level, int tc, int tr) const {
  static const float kZeros[kCells] = {};
  const std::int32_t t = tileIndex(level, tc, tr);
  return t < 0 ? kZeros : &level.cells[static_cast<std::size_t>(t) * kCells];
}

// Level h from level h - 1 (k = 2^(h-1)): the max of the four cells (c, r),
// (c + k, r), (c, r + k), (c + k, r + k), as doubling the window along x and
// then along y does (cells past the grid are 0). A tile is allocated where
// one of those cells can be non-zero: in its own tile or in the tiles from
// k to k + 7 cells right of / above it.
void PooledGrid::addLevel() {
  const int k = 1 << (levels() - 1);
  const int reach = (kMask + k) >> kBits;  // the farthest source tile, in tiles
  Level next;
  next.index.assign(static_cast<std::size_t>(tile_cols_) * tile_rows_, -1);
  const Level& prev = levels_.back();
  // The source tiles of tile (tc, tr): src[oy][ox] = tile (tc + ox, tr + oy).
  std::vector<const float*> src(static_cast<std::size_t>((reach + 1) * (reach + 1)));
  const auto at = [&](int ox, int oy) -> const float*& {
    return src[static_cast<std::size_t>(oy * (reach + 1) + ox)];
  };
  const int first = k >> kBits;  // the first tile k cells on
  for (int tr = 0; tr < tile_rows_; ++tr) {
    for (int tc = 0; tc < tile_cols_; ++tc) {
      bool needed = false;
      for (int oy = 0; oy <= reach; ++oy) {
        for (int ox = 0; ox <= reach; ++ox) {
          const bool read = (ox == 0 || ox >= first) && (oy == 0 || oy >= first);
          at(ox, oy) = read ? tile(prev, tc + ox, tr + oy) : nullptr;
          needed = needed || (read && tileIndex(prev, tc + ox, tr + oy) >= 0);
        }
      }
      if (!needed) {
        continue;
      }
      const auto t = static_cast<std::int32_t>(next.cells.size() / kCells);
      next.index[static_cast<std::size_t>(tr * tile_cols_ + tc)] = t;
      next.cells.resize(next.cells.size() + kCells);
      float* out = &next.cells[static_cast<std::size_t>(t) * kCells];
      const auto cell = [&](int x, int y) {  // level h - 1 at (x, y) cells from the tile's corner
        return at(x >> kBits, y >> kBits)[((y & kMask) << kBits) | (x & kMask)];
      };
      for (int y = 0; y < kSide; ++y) {
        for (int x = 0; x < kSide; ++x) {
          out[(y << kBits) | x] = std::max(std::max(cell(x, y), cell(x + k, y)),
                                           std::max(cell(x, y + k), cell(x + k, y + k)));
        }
      }
    }
  }
  levels_.push_back(std::move(next));
}

std::size_t PooledGrid::tiles() const {
  std::size_t n = 0;
  for (const Level& level : levels_) {
    n += level.cells.size() / kCells;
  }
  return n;
}

}  // namespace pmap::poses
