// A likelihood grid and its max-pooled levels for branch and bound
// (scan_matcher.h), stored sparsely: in tiles of 8 x 8 cells, allocated only
// where a level is non-zero. A submap of long-range scans (ACES: 1-degree
// beams to 50 m) spans 80-100 m, 2,000 x 2,000 cells of 5 cm, while its
// likelihood is non-zero only within 3 sigma of its walls: stored densely,
// its seven levels were 90 MB per candidate and building them (allocation,
// page faults, copies) was two thirds of the loop search's time. Reading a
// cell costs one more look-up (the tile's index); the values are the same
// as a dense grid's to the bit.
#pragma once

#include <cstdint>
#include <vector>

namespace pmap::poses {

class PooledGrid {
 public:
  PooledGrid() = default;
  /// An all-zero level 0 of cols x rows cells.
  PooledGrid(int cols, int rows);

  int cols() const { return cols_; }
  int rows() const { return rows_; }
  int levels() const { return static_cast<int>(levels_.size()); }
  bool empty() const { return levels_.empty(); }

  /// Level 0: cell (c, r) = max(cell, v); (c, r) must be inside the grid.
  void raise(int c, int r, float v) { raiseRow(c, r, &v, 1); }
  /// Level 0: cells (c + k, r) = max(cell, values[k]) for k in [0, n); they
  /// must be inside the grid. One tile look-up per tile the run crosses.
  void raiseRow(int c, int r, const float* values, int n);
  /// Adds levels until there are `count`: level h holds the max over
  /// [c, c + 2^h) x [r, r + 2^h) of level 0 (cells past the grid count 0).
  void pool(int count);

  /// Level h at (c, r). A window [c, c + 2^h) that starts left of (below)
  /// the grid still overlaps it: its max is that of [0, 2^h), a superset
  /// of the overlap. 0 outside.
  float at(int h, int c, int r) const {
    const int w = 1 << h;
    if (c <= -w || r <= -w || c >= cols_ || r >= rows_) {
      return 0.0f;
    }
    c = c < 0 ? 0 : c;
    r = r < 0 ? 0 : r;
    const Level& level = levels_[static_cast<std::size_t>(h)];
    const std::int32_t t =
        level.index[static_cast<std::size_t>((r >> kBits) * tile_cols_ + (c >> kBits))];
    if (t < 0) {
      return 0.0f;
    }
    return level.cells[static_cast<std::size_t>(t) * kCells +
                       static_cast<std::size_t>(((r & kMask) << kBits) | (c & kMask))];
  }

  /// Tiles allocated over all levels (for tests and reports).
  std::size_t tiles() const;

 private:
  static constexpr int kBits = 3;  ///< 8 x 8 cells per tile
  static constexpr int kSide = 1 << kBits;
  static constexpr int kMask = kSide - 1;
  static constexpr std::size_t kCells = kSide * kSide;
  struct Level {
    std::vector<std::int32_t> index;  ///< per tile, row-major: its place in cells, or -1 (zero)
    std::vector<float> cells;         ///< the allocated tiles, kCells each
  };
  /// Tile (tc, tr)'s place in level.cells, or -1 (all zero, or past the grid).
  std::int32_t tileIndex(const Level& level, int tc, int tr) const;
  /// Tile (tc, tr)'s cells, or a tile of zeros.
  const float* tile(const Level& level, int tc, int tr) const;
  void addLevel();

  int cols_ = 0, rows_ = 0;
  int tile_cols_ = 0, tile_rows_ = 0;
  std::vector<Level> levels_;
};

}  // namespace pmap::poses
