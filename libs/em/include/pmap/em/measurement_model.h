// Measurement model, eqs. (9)-(12): a measurement caused by surface j is
// Gaussian in its distance to the rectangle, sigma; the outlier class "*" is
// uniform over [0, z_max], i.e. a virtual surface at squared normalised
// distance L* = log(z_max^2 / (2 pi sigma^2)), eq. (11). Everything is kept in
// log space (scores s = -d^2 / 2 sigma^2, s* = -L*/2).
#pragma once

#include <cmath>

namespace pmap::em {

class MeasurementModel {
 public:
  MeasurementModel(double sigma_m, double z_max_m)
      : sigma_(sigma_m),
        inv_two_sigma2_(1.0 / (2.0 * sigma_m * sigma_m)),
        outlier_distance2_(std::log(z_max_m * z_max_m / (2.0 * M_PI * sigma_m * sigma_m))) {}

  double sigma() const { return sigma_; }
  /// L*: the outlier class's squared normalised distance, eq. (11).
  double outlierDistance2() const { return outlier_distance2_; }
  /// Distance beyond which a point is more outlier than inlier: sigma sqrt(L*).
  double outlierDistance() const { return sigma_ * std::sqrt(outlier_distance2_); }
  /// log of the surface term, -d^2 / 2 sigma^2 (eq. 13 without constants).
  double surfaceScore(double d2) const { return -d2 * inv_two_sigma2_; }
  /// log of the outlier term, -L*/2.
  double outlierScore() const { return -0.5 * outlier_distance2_; }
  /// Distance beyond which a surface's term is below `tolerance` times the
  /// outlier term, so its responsibility is below `tolerance`:
  /// sigma sqrt(L* + 2 ln(1/tolerance)).
  double cutoffDistance(double tolerance) const {
    return sigma_ * std::sqrt(outlier_distance2_ + 2.0 * std::log(1.0 / tolerance));
  }

 private:
  double sigma_;
  double inv_two_sigma2_;
  double outlier_distance2_;
};

}  // namespace pmap::em
