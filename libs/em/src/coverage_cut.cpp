// Coverage cuts (coverage_cut.h).
#include "pmap/em/coverage_cut.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pmap/em/cell_grid.h"
#include "pmap/em/min_area_rectangle.h"

namespace pmap::em {
namespace {

// `ids` in rect's in-plane frame (axis_u, axisV) about its centre.
std::vector<Eigen::Vector2d> inPlane(const std::vector<Eigen::Vector3d>& points,
                                     const std::vector<std::int32_t>& ids, const Rectangle& rect) {
  const Eigen::Vector3d v = rect.axisV();
  std::vector<Eigen::Vector2d> uv;
  uv.reserve(ids.size());
  for (const std::int32_t i : ids) {
    const Eigen::Vector3d d = points[static_cast<std::size_t>(i)] - rect.centre;
    uv.emplace_back(rect.axis_u.dot(d), v.dot(d));
  }
  return uv;
}

// The occupied lines of the grid along one axis ("lines" are columns for
// cuts along u, rows for cuts along v), ascending, with each line's occupied
// cells: their count and extent across. Only occupied lines are stored: a
// cut between two of them splits the members the same wherever it lies.
struct OccupiedLines {
  std::vector<std::int64_t> line;  ///< line numbers, ascending
  std::vector<std::int64_t> count, lo, hi;
  std::vector<std::int32_t> of_cell;  ///< per occupied cell: its index in `line`
};

OccupiedLines occupiedLines(const CellGrid& g, bool along_u) {
  OccupiedLines out;
  for (const GridCell& c : g.cells) {
    out.line.push_back(along_u ? c.col : c.row);
  }
  std::sort(out.line.begin(), out.line.end());
  out.line.erase(std::unique(out.line.begin(), out.line.end()), out.line.end());
  const std::size_t m = out.line.size();
  out.count.assign(m, 0);
  out.lo.assign(m, std::numeric_limits<std::int64_t>::max());
  out.hi.assign(m, std::numeric_limits<std::int64_t>::min());
  for (const GridCell& c : g.cells) {
    const auto l = static_cast<std::size_t>(
        std::lower_bound(out.line.begin(), out.line.end(), along_u ? c.col : c.row) -
        out.line.begin());
    const std::int64_t across = along_u ? c.row : c.col;
    out.of_cell.push_back(static_cast<std::int32_t>(l));
    ++out.count[l];
    out.lo[l] = std::min(out.lo[l], across);
    out.hi[l] = std::max(out.hi[l], across);
  }
  return out;
}

// Empty area (in cells) of the parts before / after each cut: the bounding
// box of a part's occupied cells minus those cells. Index t (0..m) is the cut
// with the first t occupied lines below it.
struct CutAreas {
  std::vector<double> empty_low, empty_high;
  double empty_whole = 0;
};

// Running bounding box of occupied lines, added one at a time.
struct LineBox {
  std::int64_t first = 0, last = 0, amin = 0, amax = 0, n = 0;
  bool any = false;
  void add(const OccupiedLines& o, std::size_t l) {
    first = any ? std::min(first, o.line[l]) : o.line[l];
    last = any ? std::max(last, o.line[l]) : o.line[l];
    amin = any ? std::min(amin, o.lo[l]) : o.lo[l];
    amax = any ? std::max(amax, o.hi[l]) : o.hi[l];
    n += o.count[l];
    any = true;
  }
  double empty() const {
    return any ? static_cast<double>(last - first + 1) * static_cast<double>(amax - amin + 1) -
                     static_cast<double>(n)
               : 0.0;
  }
};

CutAreas cutAreas(const OccupiedLines& o) {
  const std::size_t m = o.line.size();
  CutAreas out;
  out.empty_low.assign(m + 1, 0.0);
  out.empty_high.assign(m + 1, 0.0);
  LineBox low, high;
  for (std::size_t t = 0; t < m; ++t) {
    low.add(o, t);
    out.empty_low[t + 1] = low.empty();
    high.add(o, m - 1 - t);
    out.empty_high[m - 1 - t] = high.empty();
  }
  out.empty_whole = low.empty();
  return out;
}

// How much smaller than their bounding boxes in the grid's frame the parts
// before / after each cut become when refitted (eq. 29: each part's own
// minimum-area rectangle), in cells; 0 for parts aligned with the grid. A
// rectangle fitted around an L (a ceiling continued around a corner) is turned
// by the appendage, so in its frame neither leg looks rectangular, while
// each leg refitted alone is. Prefix (suffix) hulls grow one occupied line at
// a time: each step merges two small hulls.
struct RefitSavings {
  std::vector<double> low, high;  ///< per cut index t, as CutAreas
  double whole = 0;
};

RefitSavings refitSavings(const std::vector<Eigen::Vector2d>& uv,
                          const std::vector<std::int32_t>& line_of_member, std::size_t lines,
                          double cell_area) {
  std::vector<std::vector<Eigen::Vector2d>> line_hull(lines);
  for (std::size_t m = 0; m < uv.size(); ++m) {
    line_hull[static_cast<std::size_t>(line_of_member[m])].push_back(uv[m]);
  }
  for (auto& h : line_hull) {
    h = convexHull(std::move(h));
  }
  auto saving = [&](const std::vector<Eigen::Vector2d>& hull) {
    if (hull.size() < 3) {
      return 0.0;
    }
    Eigen::Vector2d lo = hull.front(), hi = hull.front();
    for (const Eigen::Vector2d& q : hull) {
      lo = lo.cwiseMin(q);
      hi = hi.cwiseMax(q);
    }
    const double box = (hi - lo).prod();
    return std::max(0.0, box - minAreaRectangleOfHull(hull).area()) / cell_area;
  };
  RefitSavings out;
  out.low.assign(lines + 1, 0.0);
  out.high.assign(lines + 1, 0.0);
  std::vector<Eigen::Vector2d> hull;
  for (std::size_t l = 0; l < lines; ++l) {  // lines [0, l]: the part before l + 1
    hull.insert(hull.end(), line_hull[l].begin(), line_hull[l].end());
    hull = convexHull(std::move(hull));
    out.low[l + 1] = saving(hull);
  }
  out.whole = out.low[lines];
  hull.clear();
  for (std::size_t l = lines; l-- > 0;) {  // lines [l, end): the part from l
    hull.insert(hull.end(), line_hull[l].begin(), line_hull[l].end());
    hull = convexHull(std::move(hull));
    out.high[l] = saving(hull);
  }
  return out;
}

// The rectangle in `rect`'s plane with the in-plane axes of the minimum-area
// rectangle of `part`, bounding all of `members`; none when those axes are
// already `rect`'s (within 0.2 degrees) or `part` is degenerate.
std::optional<Rectangle> frameAlong(const std::vector<Eigen::Vector3d>& points,
                                    const std::vector<std::int32_t>& part,
                                    const std::vector<std::int32_t>& members,
                                    const Rectangle& rect) {
  const Rect2D r = minAreaRectangle(inPlane(points, part, rect));
  const Eigen::Vector2d a = r.axis;
  if (r.area() <= 0.0 ||
      std::min(std::abs(a.x()), std::abs(a.y())) < std::sin(0.2 * M_PI / 180.0)) {
    return std::nullopt;
  }
  const Eigen::Vector2d b(-a.y(), a.x());
  Eigen::Vector2d lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
  for (const Eigen::Vector2d& q : inPlane(points, members, rect)) {
    const Eigen::Vector2d f(a.dot(q), b.dot(q));
    lo = lo.cwiseMin(f);
    hi = hi.cwiseMax(f);
  }
  Rectangle frame = rect;
  frame.axis_u = (a.x() * rect.axis_u + a.y() * rect.axisV()).normalized();
  const Eigen::Vector3d fv = rect.normal.cross(frame.axis_u);
  const Eigen::Vector2d mid = 0.5 * (lo + hi);
  frame.centre = rect.centre + frame.axis_u * mid.x() + fv * mid.y();
  frame.half_u = 0.5 * (hi.x() - lo.x());
  frame.half_v = 0.5 * (hi.y() - lo.y());
  return frame;
}

// One way to cut along the grid's lines: before line k, keeping `keep`.
struct CutCandidate {
  bool along_u = true;
  std::int64_t k = 0;
  CutKeep keep = CutKeep::kBoth;
  double gain = 0;
  std::size_t larger = 0;  ///< members of the larger side
};

// Every cut along one axis of the grid that gains, with its estimated gain:
// keeping both parts saves empty area at the price of kappa; keeping one
// saves more at the price of the dropped members' loss. Cut positions k
// (1..lines-1) with the same occupied lines below are one cut; it is listed
// once, at its smallest k.
void cutsAlong(bool along_u, const CellGrid& g, const std::vector<Eigen::Vector2d>& uv,
               const std::vector<double>& member_loss, double cell_area, double empty_area_cost,
               double kappa, std::size_t min_part, bool allow_trims,
               std::vector<CutCandidate>& out) {
  const std::int64_t lines = along_u ? g.cols : g.rows;
  const OccupiedLines o = occupiedLines(g, along_u);
  const std::size_t m = o.line.size();
  std::vector<std::int32_t> line_of_member(uv.size());
  // Members and loss per occupied line, then prefix sums.
  std::vector<double> loss_prefix(m + 1, 0.0);
  std::vector<std::size_t> count_prefix(m + 1, 0);
  for (std::size_t k = 0; k < uv.size(); ++k) {
    line_of_member[k] = o.of_cell[static_cast<std::size_t>(g.cell_of[k])];
    const auto l = static_cast<std::size_t>(line_of_member[k]);
    loss_prefix[l + 1] += member_loss[k];
    ++count_prefix[l + 1];
  }
  for (std::size_t l = 0; l < m; ++l) {
    loss_prefix[l + 1] += loss_prefix[l];
    count_prefix[l + 1] += count_prefix[l];
  }
  const CutAreas areas = cutAreas(o);
  const RefitSavings refit = refitSavings(uv, line_of_member, m, cell_area);
  const double whole = std::max(0.0, areas.empty_whole - refit.whole);
  const double loss_all = loss_prefix.back();
  for (std::size_t t = 0; t <= m; ++t) {
    const std::int64_t k = t == 0 ? 1 : o.line[t - 1] + 1;
    if (k > lines - 1 || (t < m && k > o.line[t])) {
      continue;
    }
    const std::size_t n_low = count_prefix[t];
    const std::size_t n_high = uv.size() - n_low;
    const double lo = std::max(0.0, areas.empty_low[t] - refit.low[t]);
    const double hi = std::max(0.0, areas.empty_high[t] - refit.high[t]);
    const std::size_t larger = std::max(n_low, n_high);
    auto add = [&](CutKeep keep, double gain, bool ok) {
      if (ok && gain > 0.0) {
        out.push_back({along_u, k, keep, gain, larger});
      }
    };
    add(CutKeep::kBoth, empty_area_cost * (whole - lo - hi) * cell_area - kappa,
        n_low >= min_part && n_high >= min_part);
    add(CutKeep::kPartA, empty_area_cost * (whole - lo) * cell_area - (loss_all - loss_prefix[t]),
        allow_trims && n_low >= min_part);
    add(CutKeep::kPartB, empty_area_cost * (whole - hi) * cell_area - loss_prefix[t],
        allow_trims && n_high >= min_part);
  }
}

// The best coverage cut along the axes of `rect` (see coverageCut). Near
// ties (within two cells of empty area: an L can be cut either way, and the
// grid's estimate differs by a cell or so between the two) go to the cut
// leaving the larger part, the canonical form.
std::optional<CoverageCut> coverageCutInFrame(const std::vector<Eigen::Vector3d>& points,
                                              const std::vector<std::int32_t>& members,
                                              const std::vector<double>& member_loss,
                                              const Rectangle& rect, double cell_m,
                                              double empty_area_cost, double kappa,
                                              std::size_t min_part, bool allow_trims) {
  const CellGrid g = gridOf(points, members, rect, cell_m);
  const std::vector<Eigen::Vector2d> uv = inPlane(points, members, rect);
  const double cell_area = cell_m * cell_m;
  std::vector<CutCandidate> cands;
  for (const bool along_u : {true, false}) {
    cutsAlong(along_u, g, uv, member_loss, cell_area, empty_area_cost, kappa, min_part, allow_trims,
              cands);
  }
  if (cands.empty()) {
    return std::nullopt;
  }
  double top = 0;
  for (const CutCandidate& c : cands) {
    top = std::max(top, c.gain);
  }
  const double tie = 2.0 * empty_area_cost * cell_area;
  const CutCandidate* pick = nullptr;
  for (const CutCandidate& c : cands) {  // the first of equals: deterministic
    if (c.gain >= top - tie && (pick == nullptr || c.larger > pick->larger ||
                                (c.larger == pick->larger && c.gain > pick->gain))) {
      pick = &c;
    }
  }
  CoverageCut cut;
  cut.keep = pick->keep;
  cut.estimated_gain = pick->gain;
  std::vector<char> in_a(g.cells.size(), 0);
  for (std::size_t c = 0; c < g.cells.size(); ++c) {
    const std::int64_t line = pick->along_u ? g.cells[c].col : g.cells[c].row;
    in_a[c] = line < pick->k ? 1 : 0;
  }
  cut.parts = partition(members, g.cell_of, in_a);
  return cut;
}

}  // namespace

std::optional<CoverageCut> coverageCut(const std::vector<Eigen::Vector3d>& points,
                                       const std::vector<std::int32_t>& members,
                                       const std::vector<double>& member_loss,
                                       const Rectangle& rect, double cell_m, double empty_area_cost,
                                       double kappa, std::size_t min_part, bool allow_trims) {
  if (members.size() < min_part) {
    return std::nullopt;
  }
  std::optional<CoverageCut> best = coverageCutInFrame(
      points, members, member_loss, rect, cell_m, empty_area_cost, kappa, min_part, allow_trims);
  if (!best) {
    return best;
  }
  // The cut's larger part gives the frame of the data's dominant piece (a
  // ceiling's first leg, free of the appendage that turned `rect`): search
  // again along its axes, where an L can be cut either way and the tie rule
  // keeps its canonical form.
  const SplitProposal& p = best->parts;
  const auto& larger = p.part_a.size() >= p.part_b.size() ? p.part_a : p.part_b;
  if (const auto frame = frameAlong(points, larger, members, rect)) {
    if (auto again = coverageCutInFrame(points, members, member_loss, *frame, cell_m,
                                        empty_area_cost, kappa, min_part, allow_trims)) {
      return again;
    }
  }
  return best;
}

std::vector<std::int32_t> cornerTransfer(const std::vector<Eigen::Vector3d>& points,
                                         const Rectangle& big,
                                         const std::vector<std::int32_t>& big_extent,
                                         const Rectangle& other,
                                         const std::vector<std::int32_t>& other_members,
                                         double sigma, const SelectionRules& rules) {
  const bool long_u = big.half_u >= big.half_v;
  const Eigen::Vector3d along = long_u ? big.axis_u : big.axisV();
  const Eigen::Vector3d across = long_u ? big.axisV() : big.axis_u;
  const double end =
      (along.dot(other.centre - big.centre) >= 0 ? 1.0 : -1.0) * std::max(big.half_u, big.half_v);
  double lo = INFINITY, hi = -INFINITY;
  for (const std::int32_t i : big_extent) {
    const Eigen::Vector3d d = points[static_cast<std::size_t>(i)] - big.centre;
    if (std::abs(along.dot(d) - end) <= rules.corner_end_window_m) {
      lo = std::min(lo, across.dot(d));
      hi = std::max(hi, across.dot(d));
    }
  }
  std::vector<std::int32_t> moving;
  // An L's other leg runs across big's axis beyond its width (collinear
  // pieces of one corridor are no L).
  double other_lo = INFINITY, other_hi = -INFINITY;
  for (const Eigen::Vector3d& c : other.corners()) {
    other_lo = std::min(other_lo, across.dot(c - big.centre));
    other_hi = std::max(other_hi, across.dot(c - big.centre));
  }
  if (!(hi > lo) || other_hi - other_lo < (hi - lo) + rules.corner_min_leg_beyond_m) {
    return moving;
  }
  std::size_t on_plane = 0, beside = 0;
  const double sign = end >= 0 ? 1.0 : -1.0;
  for (const std::int32_t i : other_members) {
    const Eigen::Vector3d& p = points[static_cast<std::size_t>(i)];
    const Eigen::Vector3d d = p - big.centre;
    const double c = across.dot(d);
    if (c >= lo - sigma && c <= hi + sigma) {
      moving.push_back(i);
      on_plane += std::abs(big.planeDistance(p)) <= rules.grow_sigmas * sigma ? 1 : 0;
      // Beside big rather than beyond its end (a room's ceiling seen through
      // a doorway next to the corridor's): no L.
      beside += sign * along.dot(d) < std::abs(end) - rules.corner_beside_margin_m ? 1 : 0;
    }
  }
  const auto on_plane_pct = static_cast<std::size_t>(rules.corner_on_plane_percent);
  const auto beside_pct = static_cast<std::size_t>(rules.corner_beside_percent);
  if (on_plane * 100 < moving.size() * on_plane_pct || beside * 100 > moving.size() * beside_pct) {
    moving.clear();
  }
  std::sort(moving.begin(), moving.end());
  return moving;
}

}  // namespace pmap::em
