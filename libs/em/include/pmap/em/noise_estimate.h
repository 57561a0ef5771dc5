// The range noise of a point set, estimated from the data (`sigma_m = auto`):
// the median, over a seeded random sample of points, of the root of the
// smallest eigenvalue of the covariance of each point's k nearest
// neighbours. On a surface that eigenvalue is the variance across it (the
// noise); at corners and on clutter it is larger, which the median ignores
// while they are fewer than half the sample. Issue 16 gives this rule (2,000
// points, 100 neighbours, a floor of 2 mm) for every method of its peer
// benchmark, ours included.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace pmap::em {

struct NoiseEstimateOptions {
  int samples = 2000;      ///< points sampled, >= 1
  int neighbours = 100;    ///< k, >= 3
  double floor_m = 0.002;  ///< the estimate is at least this (m), >= 0
  std::uint64_t seed = 1;  ///< the sample's seed
  bool validate(std::string* why) const;
};

struct NoiseEstimate {
  bool estimated = false;  ///< false: fewer points than neighbours + 1
  double sigma_m = 0;      ///< the median (floored)
  int samples = 0;         ///< points whose neighbourhood was used
  double p25_m = 0;        ///< quartiles of the per-point values (unfloored), for reports
  double p75_m = 0;
};

NoiseEstimate estimateRangeSigma(const std::vector<Eigen::Vector3d>& points,
                                 const NoiseEstimateOptions& options = {});

struct PlanarEmOptions;

/// sigma_m = auto: options.sigma_m becomes the estimate from `points` when
/// there is one and it is a valid sigma_m (options.validate: z_max_m must
/// exceed 3 sigma); otherwise options stay and the result says
/// estimated = false.
NoiseEstimate estimateSigmaInto(PlanarEmOptions& options,
                                const std::vector<Eigen::Vector3d>& points);

}  // namespace pmap::em
