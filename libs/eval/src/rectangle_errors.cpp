#include "pmap/eval/rectangle_errors.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace pmap::eval {

double normalAngleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const double na = a.norm();
  const double nb = b.norm();
  if (na == 0 || nb == 0) {
    return 90.0;
  }
  // atan2 of |cross| and |dot| stays accurate near 0 (acos does not).
  const double c = std::abs(a.dot(b)) / (na * nb);
  const double s = a.cross(b).norm() / (na * nb);
  return std::atan2(s, c) * 180.0 / M_PI;
}

double planeDistance(const Eigen::Vector3d& n, double offset_m, const Eigen::Vector3d& p) {
  return std::abs(n.dot(p) - offset_m);
}

Eigen::Vector3d rectangleCentre(const Rectangle& r) {
  return (r[0] + r[1] + r[2] + r[3]) / 4.0;
}

double cornerError(const Rectangle& map, const Rectangle& reference) {
  double best = std::numeric_limits<double>::infinity();
  for (int shift = 0; shift < 4; ++shift) {
    for (const int step : {1, -1}) {
      double sum = 0;
      for (int k = 0; k < 4; ++k) {
        const int j = ((shift + step * k) % 4 + 4) % 4;
        sum += (map[static_cast<std::size_t>(j)] - reference[static_cast<std::size_t>(k)]).norm();
      }
      best = std::min(best, sum / 4.0);
    }
  }
  return best;
}

}  // namespace pmap::eval
