// The residuals of the refinement (automatic differentiation; the residuals
// themselves are tested in tests/refine/cost_functions_test.cpp and their
// derivatives with ceres::GradientChecker).
//
// Parameter blocks of a surface: normal (3, on ceres::SphereManifold<3>),
// offset (1), rotation (1), bounds (4); see surface_params.h.
#pragma once

#include <Eigen/Core>

#include "pmap/refine/surface_params.h"

namespace pmap::refine {

/// The plane part of eq. (5) over all of a surface's measurements at once:
/// sum_i w_i (n . p_i - d)^2 / sigma^2 = (n^T A n + W (n . c - d)^2) / sigma^2
/// with the weighted centroid c, total weight W and centred scatter A of the
/// M-step (eqs. 24-27). With A = sum_k lambda_k e_k e_k^T the residuals are
/// sqrt(lambda_k) (e_k . n) / sigma (k = 0..2) and sqrt(W) (n . c - d) / sigma:
/// exact for every measurement (no subsample), and a surface that meets
/// nothing keeps the EM's plane, the minimiser of the same sum.
struct PlaneFromMoments {
  PlaneFromMoments(const Eigen::Matrix3d& scatter, const Eigen::Vector3d& centroid, double weight,
                   double sigma_m);

  template <typename T>
  bool operator()(const T* normal, const T* offset, T* residual) const {
    const Eigen::Matrix<T, 3, 1> n(normal[0], normal[1], normal[2]);
    for (int k = 0; k < 3; ++k) {
      residual[k] = rows_.row(k).cast<T>().dot(n);
    }
    residual[3] = (centroid_.cast<T>().dot(n) - offset[0]) * sqrt_weight_;
    return true;
  }

 private:
  Eigen::Matrix3d rows_;  ///< row k = sqrt(lambda_k) e_k^T / sigma
  Eigen::Vector3d centroid_;
  double sqrt_weight_;  ///< sqrt(W) / sigma
};

/// The in-plane part of eq. (5) for one measurement: how far it lies beyond
/// the rectangle's bounds along u and along v (0 inside), in units of sigma.
/// With the plane part (PlaneFromMoments) the squared sum is d^2 / sigma^2
/// of eq. (5).
struct BeyondBounds {
  BeyondBounds(const Eigen::Vector3d& point, const Eigen::Vector3d& c0, const Eigen::Vector3d& u0,
               double sigma_m)
      : p_(point), c0_(c0), u0_(u0), inv_sigma_(1.0 / sigma_m) {}

  template <typename T>
  bool operator()(const T* normal, const T* offset, const T* rotation, const T* bounds,
                  T* residual) const {
    const Frame<T> f = frameOf(normal, offset, rotation, c0_, u0_);
    const Eigen::Matrix<T, 3, 1> d = p_.cast<T>() - f.origin;
    residual[0] = beyond(f.u.dot(d), bounds[kUMin], bounds[kUMax]) * inv_sigma_;
    residual[1] = beyond(f.v.dot(d), bounds[kVMin], bounds[kVMax]) * inv_sigma_;
    return true;
  }

  template <typename T>
  static T beyond(const T& x, const T& lo, const T& hi) {
    if (x < lo)
      return lo - x;
    if (x > hi)
      return x - hi;
    return T(0);
  }

 private:
  Eigen::Vector3d p_, c0_, u0_;
  double inv_sigma_;
};

/// A seam: two points of edge `edge` of surface a (at the coordinates
/// `along` on it, seams.h) lie on the plane of surface b; residuals
/// (n_b . x - d_b) / seam_sigma. With both on b's plane the edge runs along
/// the planes' intersection line.
struct EdgeOnPlane {
  EdgeOnPlane(int edge, const std::array<double, 2>& along, const Eigen::Vector3d& c0,
              const Eigen::Vector3d& u0, double seam_sigma_m)
      : edge_(edge), along_(along), c0_(c0), u0_(u0), inv_sigma_(1.0 / seam_sigma_m) {}

  template <typename T>
  bool operator()(const T* normal, const T* offset, const T* rotation, const T* bounds,
                  const T* other_normal, const T* other_offset, T* residual) const {
    const Frame<T> f = frameOf(normal, offset, rotation, c0_, u0_);
    const Eigen::Matrix<T, 3, 1> nb(other_normal[0], other_normal[1], other_normal[2]);
    for (std::size_t i = 0; i < 2; ++i) {
      const Eigen::Matrix<T, 3, 1> x = edgePoint(f, bounds, edge_, along_[i]);
      residual[i] = (nb.dot(x) - other_offset[0]) * inv_sigma_;
    }
    return true;
  }

 private:
  int edge_;
  std::array<double, 2> along_;
  Eigen::Vector3d c0_, u0_;
  double inv_sigma_;
};

/// Faithfulness to the points' extent and frame: each bound stays near the
/// EM's fit (scale extent_sigma), the frame's turn near 0 (rotation_sigma).
struct ExtentPrior {
  ExtentPrior(const SurfaceParams& initial, double extent_sigma_m, double rotation_sigma_rad)
      : b0_(initial.bounds),
        r0_(initial.rotation),
        inv_extent_(1.0 / extent_sigma_m),
        inv_rotation_(1.0 / rotation_sigma_rad) {}

  template <typename T>
  bool operator()(const T* rotation, const T* bounds, T* residual) const {
    for (int k = 0; k < 4; ++k) {
      residual[k] = (bounds[k] - b0_[static_cast<std::size_t>(k)]) * inv_extent_;
    }
    residual[4] = (rotation[0] - r0_) * inv_rotation_;
    return true;
  }

 private:
  std::array<double, 4> b0_;
  double r0_;
  double inv_extent_, inv_rotation_;
};

/// Manhattan prior between two normals: orthogonal (residual n_a . n_b) or
/// parallel (residual n_a x n_b, sign-agnostic), scaled by 1 / sin(sigma).
struct ManhattanPrior {
  ManhattanPrior(bool orthogonal, double sigma_rad)
      : orthogonal_(orthogonal), inv_sigma_(1.0 / std::sin(sigma_rad)) {}

  template <typename T>
  bool operator()(const T* a, const T* b, T* residual) const {
    const Eigen::Matrix<T, 3, 1> na(a[0], a[1], a[2]);
    const Eigen::Matrix<T, 3, 1> nb(b[0], b[1], b[2]);
    if (orthogonal_) {
      residual[0] = na.dot(nb) * inv_sigma_;
      residual[1] = T(0);
      residual[2] = T(0);
    } else {
      const Eigen::Matrix<T, 3, 1> c = na.cross(nb);
      for (int i = 0; i < 3; ++i)
        residual[i] = c[i] * inv_sigma_;
    }
    return true;
  }

 private:
  bool orthogonal_;
  double inv_sigma_;
};

}  // namespace pmap::refine
