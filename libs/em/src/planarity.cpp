#include "pmap/em/planarity.h"

#include <Eigen/Dense>
#include <cmath>
#include <limits>

namespace pmap::em {

Planarity measurePlanarity(const std::vector<Eigen::Vector3d>& points,
                           const std::vector<std::int32_t>& members, const Rectangle& rect) {
  Planarity out;
  out.curvature_radius_m = std::numeric_limits<double>::infinity();
  if (members.size() < 12) {
    return out;
  }
  const Eigen::Vector3d u = rect.axis_u;
  const Eigen::Vector3d v = rect.axisV();
  // Scale the in-plane coordinates to ~1 for a well-conditioned system.
  const double scale = std::max({rect.half_u, rect.half_v, 1e-3});
  Eigen::Matrix<double, 6, 6> ata = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> atb = Eigen::Matrix<double, 6, 1>::Zero();
  double sum_h = 0.0;
  double sum_h2 = 0.0;
  for (const std::int32_t i : members) {
    const Eigen::Vector3d d = points[static_cast<std::size_t>(i)] - rect.centre;
    const double a = u.dot(d) / scale;
    const double b = v.dot(d) / scale;
    const double h = rect.normal.dot(d);
    Eigen::Matrix<double, 6, 1> row;
    row << a * a, a * b, b * b, a, b, 1.0;
    for (int r = 0; r < 6; ++r) {  // the lower triangle; the upper one is its mirror
      for (int c = 0; c <= r; ++c) {
        ata(r, c) += row(r) * row(c);
      }
    }
    atb += row * h;
    sum_h += h;
    sum_h2 += h * h;
  }
  ata.triangularView<Eigen::StrictlyUpper>() = ata.transpose();
  const double n = static_cast<double>(members.size());
  const double variance =
      sum_h2 - sum_h * sum_h / n;  // about the mean (linear part ~0 after the fit)
  const Eigen::Matrix<double, 6, 1> coef = ata.ldlt().solve(atb);
  const double rss = sum_h2 - 2.0 * coef.dot(atb) + coef.dot(ata * coef);
  if (!(variance > 0.0) || !coef.allFinite()) {
    return out;
  }
  out.variance_explained = std::clamp(1.0 - rss / variance, 0.0, 1.0);
  Eigen::Matrix2d hessian;
  hessian << 2.0 * coef(0), coef(1), coef(1), 2.0 * coef(2);
  hessian /= scale * scale;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(hessian);
  Eigen::Index largest = 0;
  const double k = eig.eigenvalues().cwiseAbs().maxCoeff(&largest);
  if (!(k > 0.0)) {
    return out;
  }
  out.curvature_radius_m = 1.0 / k;
  // The members' extent along the most curved direction: the bend's chord.
  const Eigen::Vector2d dir = eig.eigenvectors().col(largest);
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const std::int32_t i : members) {
    const Eigen::Vector3d d = points[static_cast<std::size_t>(i)] - rect.centre;
    const double t = dir.x() * u.dot(d) + dir.y() * v.dot(d);
    lo = std::min(lo, t);
    hi = std::max(hi, t);
  }
  out.bend_depth_m = k * (hi - lo) * (hi - lo) / 8.0;
  return out;
}

bool isCurved(const Planarity& p, double min_radius_m, double min_depth_m,
              double min_variance_explained) {
  return p.curvature_radius_m < min_radius_m && p.bend_depth_m >= min_depth_m &&
         p.variance_explained >= min_variance_explained;
}

}  // namespace pmap::em
