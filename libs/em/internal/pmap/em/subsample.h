// The sample a dense input's model selection runs on (coarse-to-fine
// offline EM, offline_em.h): a seeded uniform random subsample of the
// measurements, its own nearest-neighbour graph, and the options whose
// thresholds count points or nats scaled to it. On a uniform sample of a
// fraction f of the points every summed score (eq. 30's likelihood term) is
// f times the full one in expectation, so scaling kappa, min_gain,
// empty_area_cost and min_support by f asks the sample the same questions
// the full data would be asked.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "pmap/em/neighbours.h"
#include "pmap/em/planar_em_options.h"

namespace pmap::em {

struct Subsample {
  std::vector<std::int32_t> index;  ///< into the full measurements, ascending
  std::vector<Eigen::Vector3d> points;
  std::vector<std::int32_t> rows;  ///< empty when the full input has none
  Neighbours neighbours;           ///< up to 4 nearest sampled points
  double fraction = 1.0;           ///< sampled / all
};

/// `target` of the `points` drawn uniformly without replacement (seeded:
/// the same input and seed give the same sample), in input order. Their
/// neighbours are the 4 nearest sampled points within 2.5 times the
/// expected sample spacing, from the full input's median neighbour distance
/// (`neighbours`) scaled by 1/sqrt(fraction).
Subsample drawSubsample(const std::vector<Eigen::Vector3d>& points, const Neighbours& neighbours,
                        const std::vector<std::int32_t>& rows, std::size_t target,
                        std::uint64_t seed);

/// `o` with the thresholds that count points or nats scaled by `fraction`
/// (kappa, min_gain, empty_area_cost, convergence_absolute_nats; min_support
/// with a floor of rules.min_part_points) and coarse_points off.
PlanarEmOptions scaledToSample(const PlanarEmOptions& o, double fraction);

}  // namespace pmap::em
