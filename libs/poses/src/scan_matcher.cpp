#include "pmap/poses/scan_matcher.h"

#include "pmap/poses/free_space.h"

#include <algorithm>
#include <cmath>
#include <queue>

namespace pmap::poses {
namespace {

// Unsigned shifts: a left shift of a negative value is undefined in C++17.
std::uint64_t cellKey(std::int64_t c, std::int64_t r) {
  return (static_cast<std::uint64_t>(c) << 32) ^ (static_cast<std::uint64_t>(r) & 0xffffffffULL);
}

// The query points rotated by theta about the window's centre and placed at
// its lower corner, in grid cells.
std::vector<Eigen::Vector2i> cellsAt(const std::vector<Eigen::Vector2d>& query, double theta,
                                     const Eigen::Vector2d& corner, double res) {
  const double c = std::cos(theta), s = std::sin(theta);
  std::vector<Eigen::Vector2i> out;
  out.reserve(query.size());
  for (const Eigen::Vector2d& q : query) {
    const Eigen::Vector2d p(c * q.x() - s * q.y() + corner.x(), s * q.x() + c * q.y() + corner.y());
    out.emplace_back(static_cast<int>(std::floor(p.x() / res)),
                     static_cast<int>(std::floor(p.y() / res)));
  }
  return out;
}

// One point per voxel, then a regular subset of at most `cap` points.
std::vector<Eigen::Vector2d> thinned(const std::vector<Eigen::Vector2d>& points, double voxel,
                                     int cap) {
  std::unordered_map<std::uint64_t, int> seen;
  std::vector<Eigen::Vector2d> out;
  for (const auto& p : points) {
    const auto c = static_cast<std::int64_t>(std::floor(p.x() / voxel));
    const auto r = static_cast<std::int64_t>(std::floor(p.y() / voxel));
    if (seen.emplace(cellKey(c, r), 0).second) {
      out.push_back(p);
    }
  }
  if (static_cast<int>(out.size()) <= cap) {
    return out;
  }
  std::vector<Eigen::Vector2d> kept;
  const double stride = static_cast<double>(out.size()) / cap;
  for (int i = 0; i < cap; ++i) {
    kept.push_back(out[static_cast<std::size_t>(i * stride)]);
  }
  return kept;
}

}  // namespace

bool ScanMatchOptions::validate(std::string* why) const {
  if (!(resolution_m > 0.0) || !(sigma_m > 0.0) || !(max_angle_step_deg > 0.0)) {
    *why = "resolution_m, sigma_m and max_angle_step_deg must be > 0";
    return false;
  }
  if (levels < 1 || levels > 12 || max_query_points < 3) {
    *why = "levels must be in [1, 12], max_query_points >= 3";
    return false;
  }
  if (!(min_angle_step_deg > 0.0) || min_angle_step_deg > max_angle_step_deg ||
      !(query_voxel_m > 0.0) || !(max_gap_m >= 0.0)) {
    *why = "0 < min_angle_step_deg <= max_angle_step_deg, query_voxel_m > 0, max_gap_m >= 0";
    return false;
  }
  return true;
}

ScanMatcher::ScanMatcher(const std::vector<Eigen::Vector2d>& reference, ScanMatchOptions options)
    : options_(options) {
  if (!reference.empty()) {
    const auto dense = densified(reference, options_.max_gap_m, 0.5 * options_.resolution_m);
    buildGrid(dense);
  }
}

void ScanMatcher::buildGrid(const std::vector<Eigen::Vector2d>& reference) {
  const double res = options_.resolution_m;
  const double reach = 3.0 * options_.sigma_m;
  Eigen::Vector2d lo = reference.front(), hi = reference.front();
  for (const auto& p : reference) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  grid_.x0 = lo.x() - reach - res;
  grid_.y0 = lo.y() - reach - res;
  const int cols = static_cast<int>(std::ceil((hi.x() - lo.x() + 2 * reach) / res)) + 3;
  const int rows = static_cast<int>(std::ceil((hi.y() - lo.y() + 2 * reach) / res)) + 3;
  grid_.levels = PooledGrid(cols, rows);
  const int r = static_cast<int>(std::ceil(reach / res));
  const double inv2s2 = 1.0 / (2.0 * options_.sigma_m * options_.sigma_m);
  // exp(-|c - p|^2 / 2 s^2) = exp(-dx^2 / 2 s^2) exp(-dy^2 / 2 s^2): 2 (2r + 1)
  // exponentials per point instead of (2r + 1)^2.
  std::vector<double> gx(static_cast<std::size_t>(2 * r + 1)), gy(gx.size());
  std::vector<float> row(gx.size());  // one row of a point's cells
  for (const auto& p : reference) {
    const int pc = static_cast<int>(std::floor((p.x() - grid_.x0) / res));
    const int pr = static_cast<int>(std::floor((p.y() - grid_.y0) / res));
    for (int d = -r; d <= r; ++d) {
      const double dx = grid_.x0 + (pc + d + 0.5) * res - p.x();
      const double dy = grid_.y0 + (pr + d + 0.5) * res - p.y();
      gx[static_cast<std::size_t>(d + r)] = std::exp(-dx * dx * inv2s2);
      gy[static_cast<std::size_t>(d + r)] = std::exp(-dy * dy * inv2s2);
    }
    const int c0 = std::max(pc - r, 0), c1 = std::min(pc + r, cols - 1);
    for (int dr = -r; dr <= r; ++dr) {
      const int rr = pr + dr;
      if (rr < 0 || rr >= rows || c0 > c1) {
        continue;
      }
      for (int c = c0; c <= c1; ++c) {
        row[static_cast<std::size_t>(c - c0)] = static_cast<float>(
            gx[static_cast<std::size_t>(c - pc + r)] * gy[static_cast<std::size_t>(dr + r)]);
      }
      grid_.levels.raiseRow(c0, rr, row.data(), c1 - c0 + 1);
    }
  }
  grid_.levels.pool(options_.levels);
}

// Branch and bound over the translations of one window, all angles at once.
struct ScanMatcher::Search {
  struct Block {
    double bound = 0;  ///< mean max-pooled likelihood: >= every offset's score in the block
    int angle = 0;
    int x = 0, y = 0;  ///< lower offset (cells)
    int level = 0;     ///< the block is 2^level cells wide
    bool operator>(const Block& o) const { return bound > o.bound; }
  };
  const Grid& grid;
  std::vector<std::vector<Eigen::Vector2i>> cells;  ///< per angle
  int width = 0;                                    ///< offsets per axis
  double best = 0;
  Block best_block;
  bool found = false;
  bool first_only = false;  ///< stop at the first pose scoring more than best (anyOutside)
  /// Level-0 blocks inside this box (angle and cell offsets, inclusive) do
  /// not count (matchOutside); empty when lo > hi.
  int ex_a0 = 1, ex_a1 = 0, ex_x0 = 0, ex_x1 = -1, ex_y0 = 0, ex_y1 = -1;
  /// ... and so are the offsets of those angles within band_w cells of the
  /// line through (band_x, band_y) (cell offsets) whose unit normal is
  /// (band_nx, band_ny); none when band_w < 0.
  double band_x = 0, band_y = 0, band_nx = 0, band_ny = 1, band_w = -1;
  bool inBand(double x, double y) const {
    return std::abs(band_nx * (x - band_x) + band_ny * (y - band_y)) <= band_w;
  }
  /// The whole block is excluded: none of its offsets counts, at any level.
  bool excluded(const Block& b) const {
    if (b.angle < ex_a0 || b.angle > ex_a1) {
      return false;
    }
    const int last = (1 << b.level) - 1;
    if (b.x >= ex_x0 && b.x + last <= ex_x1 && b.y >= ex_y0 && b.y + last <= ex_y1) {
      return true;
    }
    // A band is convex: the block is inside when its four corners are.
    return band_w >= 0 && inBand(b.x, b.y) && inBand(b.x + last, b.y) && inBand(b.x, b.y + last) &&
           inBand(b.x + last, b.y + last);
  }

  double bound(const Block& b) const {
    double sum = 0;
    for (const auto& c : cells[static_cast<std::size_t>(b.angle)]) {
      sum += grid.at(b.level, c.x() + b.x, c.y() + b.y);
    }
    return sum / static_cast<double>(cells[static_cast<std::size_t>(b.angle)].size());
  }

  void descend(std::vector<Block> blocks) {
    std::sort(blocks.begin(), blocks.end(), std::greater<Block>());
    for (const Block& b : blocks) {
      if (b.bound <= best || (first_only && found)) {
        return;  // sorted: no later block can do better
      }
      if (excluded(b)) {
        continue;
      }
      if (b.level == 0) {
        best = b.bound;  // at level 0 the bound is the score
        best_block = b;
        found = true;
        continue;
      }
      std::vector<Block> children;
      const int half = 1 << (b.level - 1);
      for (int dy = 0; dy < 2; ++dy) {
        for (int dx = 0; dx < 2; ++dx) {
          Block c{0, b.angle, b.x + dx * half, b.y + dy * half, b.level - 1};
          if (c.x < width && c.y < width) {
            c.bound = bound(c);
            children.push_back(c);
          }
        }
      }
      descend(std::move(children));
    }
  }
};

ScanMatch ScanMatcher::match(const std::vector<Eigen::Vector2d>& query_in,
                             const MatchWindow& window, double min_score) const {
  MatchWindow none;
  none.linear_m = -1.0;  // excludes nothing
  return matchOutside(query_in, window, none, min_score);
}

ScanMatch ScanMatcher::matchOutside(const std::vector<Eigen::Vector2d>& query,
                                    const MatchWindow& window, const MatchWindow& excluded,
                                    double min_score) const {
  return search(query, window, excluded, min_score, false, Band{});
}

bool ScanMatcher::anyOutside(const std::vector<Eigen::Vector2d>& query, const MatchWindow& window,
                             const MatchWindow& excluded, double min_score) const {
  return search(query, window, excluded, min_score, true, Band{}).found;
}

bool ScanMatcher::anyOutsideBand(const std::vector<Eigen::Vector2d>& query,
                                 const MatchWindow& window, const MatchWindow& excluded,
                                 const Eigen::Vector2d& axis, double band_m,
                                 double min_score) const {
  Band band;
  band.axis = axis.normalized();
  band.half_width_m = band_m;
  return search(query, window, excluded, min_score, true, band).found;
}

ScanMatch ScanMatcher::search(const std::vector<Eigen::Vector2d>& query_in,
                              const MatchWindow& window, const MatchWindow& excluded,
                              double min_score, bool first_only, const Band& band) const {
  const std::vector<Eigen::Vector2d> query =
      thinned(query_in, options_.query_voxel_m, options_.max_query_points);
  if (query.empty() || grid_.levels.empty()) {
    return ScanMatch{};
  }
  const double res = options_.resolution_m;
  double max_range = res;
  for (const auto& q : query) {
    max_range = std::max(max_range, q.norm());
  }
  // An angle step that moves the farthest point by about one cell.
  const double step = std::clamp(res / max_range, options_.min_angle_step_deg * M_PI / 180.0,
                                 options_.max_angle_step_deg * M_PI / 180.0);
  const int n_angles = static_cast<int>(std::ceil(window.angular_deg * M_PI / 180.0 / step));
  Search bnb{grid_,     {}, static_cast<int>(std::ceil(2.0 * window.linear_m / res)) + 1,
             min_score, {}, false,
             first_only};
  const Eigen::Vector2d corner(window.guess.x - window.linear_m - grid_.x0,
                               window.guess.y - window.linear_m - grid_.y0);
  if (excluded.linear_m >= 0.0) {
    const auto cell = [&](double v, double lo) {
      return static_cast<int>(std::lround((v - lo) / res));
    };
    const double x_lo = window.guess.x - window.linear_m, y_lo = window.guess.y - window.linear_m;
    bnb.ex_x0 = cell(excluded.guess.x - excluded.linear_m, x_lo);
    bnb.ex_x1 = cell(excluded.guess.x + excluded.linear_m, x_lo);
    bnb.ex_y0 = cell(excluded.guess.y - excluded.linear_m, y_lo);
    bnb.ex_y1 = cell(excluded.guess.y + excluded.linear_m, y_lo);
    const double da = wrapAngle(excluded.guess.theta - window.guess.theta) / step;
    const double ha = excluded.angular_deg * M_PI / 180.0 / step;
    bnb.ex_a0 = static_cast<int>(std::floor(da - ha)) + n_angles;
    bnb.ex_a1 = static_cast<int>(std::ceil(da + ha)) + n_angles;
    if (band.half_width_m >= 0.0) {
      bnb.band_x = (excluded.guess.x - x_lo) / res;
      bnb.band_y = (excluded.guess.y - y_lo) / res;
      bnb.band_nx = -band.axis.y();
      bnb.band_ny = band.axis.x();
      bnb.band_w = band.half_width_m / res;
    }
  }
  const int top = options_.levels - 1;
  bnb.cells.resize(static_cast<std::size_t>(2 * n_angles + 1));
  // The top-level blocks of angle index a, appended to `out`.
  const auto add_roots = [&](int a, std::vector<Search::Block>& out) {
    bnb.cells[static_cast<std::size_t>(a)] =
        cellsAt(query, window.guess.theta + (a - n_angles) * step, corner, res);
    for (int y = 0; y < bnb.width; y += 1 << top) {
      for (int x = 0; x < bnb.width; x += 1 << top) {
        Search::Block b{0, a, x, y, top};
        b.bound = bnb.bound(b);
        out.push_back(b);
      }
    }
  };
  // Any pose above min_score will do for anyOutside(): the angles of the
  // excluded heading first, one at a time (a corridor's runner-up lies
  // there, found before the bounds of every angle's blocks are made), then
  // the rest best first. The full search (match) goes best first at once.
  int first_a0 = 0, first_a1 = -1;  // the angles searched one at a time
  if (first_only && excluded.linear_m >= 0.0) {
    first_a0 = std::max(bnb.ex_a0, 0);
    first_a1 = std::min(bnb.ex_a1, 2 * n_angles);
    for (int a = first_a0; a <= first_a1 && !bnb.found; ++a) {
      std::vector<Search::Block> roots;
      add_roots(a, roots);
      bnb.descend(std::move(roots));
    }
  }
  if (!bnb.found) {
    std::vector<Search::Block> roots;
    for (int a = 0; a <= 2 * n_angles; ++a) {
      if (a < first_a0 || a > first_a1) {
        add_roots(a, roots);
      }
    }
    bnb.descend(std::move(roots));
  }
  if (!bnb.found) {
    return ScanMatch{};
  }
  const Search::Block& b = bnb.best_block;
  const Pose2 best{window.guess.x - window.linear_m + b.x * res,
                   window.guess.y - window.linear_m + b.y * res,
                   wrapAngle(window.guess.theta + (b.angle - n_angles) * step)};
  return ScanMatch{true, best, bnb.best};
}

}  // namespace pmap::poses
