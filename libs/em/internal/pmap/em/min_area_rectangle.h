// Eq. (29): the smallest-area rectangle in the plane containing the
// projections of the points most likely caused by a surface. Exact: the
// optimum has a side collinear with an edge of the 2D convex hull (Freeman &
// Shapira 1975), so rotating calipers over the hull edges find it in
// O(n log n). The paper probed orientations in 1-degree steps; that variant is
// kept for comparison (benchmarks, tests).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace pmap::em {

struct Rect2D {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  Eigen::Vector2d axis = Eigen::Vector2d::UnitX();  ///< unit direction of the first side
  double half_a = 0.0;                              ///< half extent along axis
  double half_b = 0.0;                              ///< half extent along the perpendicular
  double area() const { return 4.0 * half_a * half_b; }
};

/// Convex hull, counter-clockwise, no collinear points (Andrew's monotone
/// chain). Fewer than 3 distinct points give those points.
std::vector<Eigen::Vector2d> convexHull(std::vector<Eigen::Vector2d> points);

/// Indices of the convex hull vertices of `points`, counter-clockwise (the
/// same hull as convexHull; duplicates give their first index).
std::vector<std::size_t> convexHullIndices(const std::vector<Eigen::Vector2d>& points);

/// Exact minimum-area enclosing rectangle (rotating calipers on the hull).
/// Empty input: a zero rectangle at the origin. Degenerate (collinear or
/// coincident) input: a zero-width rectangle along the points.
Rect2D minAreaRectangle(const std::vector<Eigen::Vector2d>& points);

/// The same for a hull as convexHull() returns it (counter-clockwise, no
/// collinear points): its rectangle without computing the hull again.
Rect2D minAreaRectangleOfHull(const std::vector<Eigen::Vector2d>& hull);

/// The paper's approximation: the tightest axis-aligned box over orientations
/// probed every `step_deg` degrees in [0, 90).
Rect2D probedMinAreaRectangle(const std::vector<Eigen::Vector2d>& points, double step_deg = 1.0);

}  // namespace pmap::em
