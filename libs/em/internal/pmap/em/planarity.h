// Is a set of points a plane or a curved object? A plane laid on a bin
// explains a band of points up to the outlier distance and gains likelihood,
// so likelihood and the penalty kappa alone do not reject it. The Gaussian
// model says a surface's residuals are noise; a bin's are a systematic
// curve. This test fits h = a u^2 + b uv + c v^2 + d u + e v + f to the
// points' heights h above the plane; when the quadratic explains a real part
// of the residual variance, its principal curvatures measure the bending.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "pmap/em/rectangle.h"
#include "pmap/em/selection_rules.h"

namespace pmap::em {

struct Planarity {
  double curvature_radius_m = 0.0;  ///< 1 / largest |principal curvature|; inf if flat
  double variance_explained = 0.0;  ///< share of the residual variance the quadratic explains
  /// How deep the bend is across the members: k L^2 / 8 for the largest
  /// |principal curvature| k and the members' extent L along its direction
  /// (the sagitta of that arc) (m); 0 if flat.
  double bend_depth_m = 0.0;
};

Planarity measurePlanarity(const std::vector<Eigen::Vector3d>& points,
                           const std::vector<std::int32_t>& members, const Rectangle& rect);

/// True when the points bend with a radius below `min_radius_m`, the bend
/// is at least `min_depth_m` deep across them and it explains at least
/// `min_variance_explained` of the residual variance
/// (SelectionRules::curved_min_*).
bool isCurved(const Planarity& p, double min_radius_m, double min_depth_m,
              double min_variance_explained = SelectionRules{}.curved_min_variance_explained);

}  // namespace pmap::em
