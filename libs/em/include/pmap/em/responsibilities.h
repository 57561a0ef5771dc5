// E-step, eqs. (17)-(18), in log space: for every measurement the
// expectations e_ij of being caused by surface j and e_i* of being an
// outlier, stored sparsely (only surfaces within the cutoff distance).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "pmap/em/measurement_model.h"
#include "pmap/em/rectangle_index.h"
#include "pmap/em/surface.h"

namespace pmap::em {

struct Responsibilities {
  /// Entries of point i: [offsets[i], offsets[i+1]).
  std::vector<std::uint32_t> offsets;
  std::vector<std::int32_t> surface;  ///< surface index of each entry
  std::vector<double> score;          ///< log surface term, -d^2 / 2 sigma^2
  std::vector<double> weight;         ///< e_ij
  std::vector<double> outlier;        ///< e_i*
  std::vector<std::int32_t> best;     ///< most likely cause: surface index, -1 = outlier
  std::vector<double> loglik;         ///< l_i = log(exp(s*) + sum_j exp(s_ij))
  double total_loglik = 0.0;          ///< sum of l_i (chunk-ordered sum)

  std::size_t points() const { return outlier.size(); }
};

/// Runs the E-step. `index` must index `surfaces` inflated by the model's
/// cutoff distance for `tolerance`.
void computeResponsibilities(const std::vector<Eigen::Vector3d>& points,
                             const std::vector<Surface>& surfaces, const RectangleIndex& index,
                             const MeasurementModel& model, double tolerance, int threads,
                             Responsibilities& out);

/// log(exp(a) + exp(b)) without overflow.
double logAddExp(double a, double b);

}  // namespace pmap::em
