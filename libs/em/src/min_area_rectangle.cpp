#include "pmap/em/min_area_rectangle.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace pmap::em {
namespace {

double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// The bounding box of `pts` in the frame (axis, perp(axis)).
Rect2D boxAlong(const std::vector<Eigen::Vector2d>& pts, const Eigen::Vector2d& axis) {
  const Eigen::Vector2d perp(-axis.y(), axis.x());
  double amin = std::numeric_limits<double>::infinity();
  double amax = -amin;
  double bmin = amin;
  double bmax = -amin;
  for (const auto& p : pts) {
    const double a = axis.dot(p);
    const double b = perp.dot(p);
    amin = std::min(amin, a);
    amax = std::max(amax, a);
    bmin = std::min(bmin, b);
    bmax = std::max(bmax, b);
  }
  Rect2D r;
  r.axis = axis;
  r.half_a = 0.5 * (amax - amin);
  r.half_b = 0.5 * (bmax - bmin);
  r.centre = axis * (0.5 * (amin + amax)) + perp * (0.5 * (bmin + bmax));
  return r;
}

}  // namespace

namespace {

// Akl-Toussaint: points strictly inside the octagon of the extreme points in
// 8 directions cannot be on the hull; on a dense surface that is nearly all
// of them, so the sort below sees only a thin boundary band. Returns the
// indices of the other points, in order (the first point wins ties for an
// extreme).
std::vector<std::size_t> notInsideOctagon(const std::vector<Eigen::Vector2d>& p) {
  // Directions (1, 0), (1, 1), (0, 1), (-1, 1) and their opposites: the
  // projections x, x + y, y, y - x and their negatives. The opposite
  // direction's maximum is the minimum (negation is exact).
  std::array<std::size_t, 8> ext{};
  auto sums = [](const Eigen::Vector2d& q) {
    return std::array<double, 4>{q.x(), q.x() + q.y(), q.y(), -q.x() + q.y()};
  };
  std::array<double, 4> hi = sums(p[0]);
  std::array<double, 4> lo = hi;
  for (std::size_t i = 1; i < p.size(); ++i) {
    const std::array<double, 4> v = sums(p[i]);
    for (std::size_t d = 0; d < 4; ++d) {
      if (v[d] > hi[d]) {
        hi[d] = v[d];
        ext[d] = i;
      }
      if (v[d] < lo[d]) {
        lo[d] = v[d];
        ext[d + 4] = i;
      }
    }
  }
  std::vector<Eigen::Vector2d> poly;
  for (const std::size_t e : ext) {
    if (poly.empty() || poly.back() != p[e]) {
      poly.push_back(p[e]);
    }
  }
  std::vector<std::size_t> kept;
  if (poly.size() < 3) {
    kept.resize(p.size());
    std::iota(kept.begin(), kept.end(), std::size_t{0});
    return kept;
  }
  // The octagon's edges (counter-clockwise), as origin and direction.
  struct Edge {
    double ax, ay, dx, dy;
  };
  std::vector<Edge> edges;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const Eigen::Vector2d& a = poly[k];
    const Eigen::Vector2d& b = poly[(k + 1) % poly.size()];
    if (a != b) {
      edges.push_back({a.x(), a.y(), b.x() - a.x(), b.y() - a.y()});
    }
  }
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double qx = p[i].x();
    const double qy = p[i].y();
    bool inside = true;
    for (const Edge& e : edges) {
      if (e.dx * (qy - e.ay) - e.dy * (qx - e.ax) <= 0) {
        inside = false;  // on or outside an edge
        break;
      }
    }
    if (!inside) {
      kept.push_back(i);
    }
  }
  return kept;
}

void dropInterior(std::vector<Eigen::Vector2d>& p) {
  std::vector<Eigen::Vector2d> kept;
  for (const std::size_t i : notInsideOctagon(p)) {
    kept.push_back(p[i]);
  }
  p.swap(kept);
}

}  // namespace

std::vector<Eigen::Vector2d> convexHull(std::vector<Eigen::Vector2d> p) {
  if (p.size() > 64) {
    dropInterior(p);
  }
  std::sort(p.begin(), p.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) {
    return p;
  }
  std::vector<Eigen::Vector2d> hull(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); ++i) {  // lower hull
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) {
      --k;
    }
    hull[k++] = p[i];
  }
  for (size_t i = p.size() - 1, t = k + 1; i-- > 0;) {  // upper hull
    while (k >= t && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) {
      --k;
    }
    hull[k++] = p[i];
  }
  hull.resize(k - 1);
  return hull;
}

Rect2D minAreaRectangle(const std::vector<Eigen::Vector2d>& points) {
  return points.empty() ? Rect2D{} : minAreaRectangleOfHull(convexHull(points));
}

Rect2D minAreaRectangleOfHull(const std::vector<Eigen::Vector2d>& hull) {
  if (hull.empty()) {
    return {};
  }
  if (hull.size() == 1) {
    Rect2D r;
    r.centre = hull[0];
    return r;
  }
  if (hull.size() == 2) {
    return boxAlong(hull, (hull[1] - hull[0]).normalized());
  }
  // One side of the optimum lies on a hull edge. Rotating calipers: for each
  // edge i (direction e, inward normal n), the extreme hull vertices along +e,
  // -e and n only move forward around the hull as i advances.
  const size_t h = hull.size();
  auto at = [&](size_t k) -> const Eigen::Vector2d& { return hull[k % h]; };
  size_t right = 0;
  size_t top = 0;
  size_t left = 0;
  Rect2D best;
  double best_area = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < h; ++i) {
    const Eigen::Vector2d e = (at(i + 1) - at(i)).normalized();
    const Eigen::Vector2d n(-e.y(), e.x());
    if (i == 0) {
      right = top = left = 0;
    }
    right = std::max(right, i);
    while (e.dot(at(right + 1)) > e.dot(at(right)) + 1e-15) {
      ++right;
    }
    top = std::max(top, right);
    while (n.dot(at(top + 1)) > n.dot(at(top)) + 1e-15) {
      ++top;
    }
    left = std::max(left, top);
    while (e.dot(at(left + 1)) < e.dot(at(left)) - 1e-15) {
      ++left;
    }
    const double a0 = e.dot(at(left));
    const double a1 = e.dot(at(right));
    const double b0 = n.dot(at(i));
    const double b1 = n.dot(at(top));
    const double area = (a1 - a0) * (b1 - b0);
    if (area < best_area) {
      best_area = area;
      best.axis = e;
      best.half_a = 0.5 * (a1 - a0);
      best.half_b = 0.5 * (b1 - b0);
      best.centre = e * (0.5 * (a0 + a1)) + n * (0.5 * (b0 + b1));
    }
  }
  return best;
}

Rect2D probedMinAreaRectangle(const std::vector<Eigen::Vector2d>& points, double step_deg) {
  if (points.empty()) {
    return {};
  }
  Rect2D best;
  double best_area = std::numeric_limits<double>::infinity();
  for (double deg = 0.0; deg < 90.0; deg += step_deg) {
    const double a = deg * M_PI / 180.0;
    const Rect2D r = boxAlong(points, Eigen::Vector2d(std::cos(a), std::sin(a)));
    if (r.area() < best_area) {
      best_area = r.area();
      best = r;
    }
  }
  return best;
}

}  // namespace pmap::em

namespace pmap::em {

std::vector<std::size_t> convexHullIndices(const std::vector<Eigen::Vector2d>& points) {
  // Andrew's monotone chain over sorted indices, after the same interior
  // filter as convexHull.
  std::vector<std::size_t> idx;
  if (points.size() > 64) {
    idx = notInsideOctagon(points);
  } else {
    idx.resize(points.size());
    std::iota(idx.begin(), idx.end(), std::size_t{0});
  }
  auto less = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  };
  std::stable_sort(idx.begin(), idx.end(),
                   [&](std::size_t x, std::size_t y) { return less(points[x], points[y]); });
  // Equal points: the first occurrence is kept.
  idx.erase(std::unique(idx.begin(), idx.end(),
                        [&](std::size_t x, std::size_t y) { return points[x] == points[y]; }),
            idx.end());
  if (idx.size() < 3) {
    return idx;
  }
  std::vector<std::size_t> hull(2 * idx.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < idx.size(); ++i) {
    while (k >= 2 && cross(points[hull[k - 2]], points[hull[k - 1]], points[idx[i]]) <= 0) {
      --k;
    }
    hull[k++] = idx[i];
  }
  for (std::size_t i = idx.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(points[hull[k - 2]], points[hull[k - 1]], points[idx[i]]) <= 0) {
      --k;
    }
    hull[k++] = idx[i];
  }
  hull.resize(k - 1);
  return hull;
}

}  // namespace pmap::em
