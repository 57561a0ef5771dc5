// The templated residual of pose_graph.h (Ceres autodiff needs it inline).
#pragma once

#include <cmath>

namespace pmap::poses {

namespace detail {

/// a wrapped to [-pi, pi): a - 2 pi floor((a + pi) / 2 pi); the derivative
/// passes through unchanged (floor's is zero).
template <typename T>
T wrapped(const T& a) {
  using std::floor;
  const double two_pi = 2.0 * M_PI;
  return a - two_pi * floor((a + M_PI) / two_pi);
}

}  // namespace detail

template <typename T>
void edgeResidual(const T* ti, const T* thi, const T* tj, const T* thj, const Pose2& z,
                  const Eigen::Matrix3d& sqrt_information, T* residual) {
  using std::cos;
  using std::sin;
  const T c = cos(thi[0]);
  const T s = sin(thi[0]);
  const T dx = tj[0] - ti[0];
  const T dy = tj[1] - ti[1];
  T e[3];
  e[0] = c * dx + s * dy - z.x;  // R(theta_i)^T (t_j - t_i) - (dx, dy)
  e[1] = -s * dx + c * dy - z.y;
  e[2] = detail::wrapped(thj[0] - thi[0] - z.theta);
  for (int r = 0; r < 3; ++r) {
    residual[r] = sqrt_information(r, 0) * e[0] + sqrt_information(r, 1) * e[1] +
                  sqrt_information(r, 2) * e[2];
  }
}

}  // namespace pmap::poses
