#include "pmap/refine/cost_functions.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace pmap::refine {

PlaneFromMoments::PlaneFromMoments(const Eigen::Matrix3d& scatter, const Eigen::Vector3d& centroid,
                                   double weight, double sigma_m)
    : centroid_(centroid), sqrt_weight_(std::sqrt(std::max(weight, 0.0)) / sigma_m) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (scatter + scatter.transpose()));
  for (int k = 0; k < 3; ++k) {
    const double lambda = std::max(eig.eigenvalues()(k), 0.0);
    rows_.row(k) = std::sqrt(lambda) / sigma_m * eig.eigenvectors().col(k).transpose();
  }
}

}  // namespace pmap::refine
