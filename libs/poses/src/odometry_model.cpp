#include "pmap/poses/odometry_model.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace pmap::poses {
namespace {

constexpr double kDegree = M_PI / 180.0;
constexpr int kMaxFitIterations = 10;

// P(c) of eq. (O1) and its Jacobian A = dP/dc, c = (a, g, b).
struct Prediction {
  Eigen::Vector3d mean;
  Eigen::Matrix3d jacobian;
};

Prediction predict(const Eigen::Vector3d& u, double path_m, const Eigen::Vector3d& c) {
  const double phi = c(1) * u(2) + c(2) * path_m;
  const double h = 0.5 * phi, ch = std::cos(h), sh = std::sin(h);
  const Eigen::Vector2d turned(ch * u(0) - sh * u(1), sh * u(0) + ch * u(1));
  const Eigen::Vector2d d_turned(-sh * u(0) - ch * u(1), ch * u(0) - sh * u(1));  // d/dh
  Prediction p;
  p.mean << (1.0 + c(0)) * turned, u(2) + phi;
  Eigen::Vector3d d_phi;  // dP/dphi
  d_phi << 0.5 * (1.0 + c(0)) * d_turned, 1.0;
  p.jacobian.col(0) << turned, 0.0;
  p.jacobian.col(1) = d_phi * u(2);
  p.jacobian.col(2) = d_phi * path_m;
  return p;
}

Eigen::Vector3d vec(const Pose2& p) {
  return {p.x, p.y, p.theta};
}

Eigen::Vector3d difference(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return {a(0) - b(0), a(1) - b(1), wrapAngle(a(2) - b(2))};
}

}  // namespace

bool OdometryModelOptions::validate(std::string* why) const {
  const double positive[] = {noise_fraction,        noise_min_m,        noise_deg_per_m,
                             noise_min_deg,         scale_sigma,        turn_sigma,
                             drift_sigma_deg_per_m, calibration_path_m, huber_chi};
  for (const double v : positive) {
    if (!(v > 0.0) || !std::isfinite(v)) {
      *why =
          "odometry noise, calibration priors, odometry_calibration_path_m and "
          "odometry_calibration_huber_chi must be finite and > 0";
      return false;
    }
  }
  if (!(noise_turn_fraction >= 0.0 && noise_turn_fraction <= 1.0) || noise_fraction > 1.0 ||
      scale_sigma > 1.0 || turn_sigma > 1.0 || drift_sigma_deg_per_m > 90.0) {
    *why =
        "odometry_noise_turn_fraction must be in [0, 1], odometry_noise_fraction and the scale "
        "and turn calibration sigmas <= 1, the drift sigma <= 90 deg/m";
    return false;
  }
  return true;
}

OdometryModel::OdometryModel(OdometryModelOptions options) : options_(options) {
  calibration_.covariance =
      Eigen::Vector3d(std::pow(options_.scale_sigma, 2), std::pow(options_.turn_sigma, 2),
                      std::pow(options_.drift_sigma_deg_per_m * kDegree, 2))
          .asDiagonal();
}

MotionPrior OdometryModel::prior(const OdometrySample& from, const OdometrySample& to) const {
  const Eigen::Vector3d u = vec(between(from.pose, to.pose));
  const double l = std::max(0.0, to.path_m - from.path_m);
  const Eigen::Vector3d c(calibration_.scale, calibration_.turn, calibration_.drift_rad_per_m);
  const Prediction p = predict(u, l, c);
  // eq. (O2), then (O4)
  const double sigma_t = std::max(options_.noise_min_m, options_.noise_fraction * l);
  const double sigma_r = std::max(options_.noise_min_deg, options_.noise_deg_per_m * l) * kDegree +
                         options_.noise_turn_fraction * std::abs(u(2));
  Eigen::Matrix3d cov =
      Eigen::Vector3d(sigma_t * sigma_t, sigma_t * sigma_t, sigma_r * sigma_r).asDiagonal();
  cov += p.jacobian * calibration_.covariance * p.jacobian.transpose();
  MotionPrior out;
  out.mean = {p.mean(0), p.mean(1), wrapAngle(p.mean(2))};
  const Eigen::Matrix3d information = cov.inverse();
  out.information = 0.5 * (information + information.transpose());
  return out;
}

void OdometryModel::addEdge(const OdometrySample& from, const OdometrySample& to, const Pose2& z,
                            const Eigen::Matrix3d& w) {
  const Eigen::Vector3d zv = vec(z);
  if (!w.allFinite() || !zv.allFinite()) {
    return;
  }
  edges_.push_back({vec(between(from.pose, to.pose)), std::max(0.0, to.path_m - from.path_m),
                    to.path_m, zv, 0.5 * (w + w.transpose())});
  while (edges_.back().end_path_m - edges_.front().end_path_m > options_.calibration_path_m) {
    edges_.pop_front();
  }
  fit();
}

// eq. (O3): Gauss-Newton with Huber weights (IRLS), from the last fit.
void OdometryModel::fit() {
  const Eigen::Matrix3d n0 =
      Eigen::Vector3d(1.0 / std::pow(options_.scale_sigma, 2),
                      1.0 / std::pow(options_.turn_sigma, 2),
                      1.0 / std::pow(options_.drift_sigma_deg_per_m * kDegree, 2))
          .asDiagonal();
  Eigen::Vector3d c(calibration_.scale, calibration_.turn, calibration_.drift_rad_per_m);
  Eigen::Matrix3d n = n0;
  for (int it = 0; it < kMaxFitIterations; ++it) {
    n = n0;
    Eigen::Vector3d g = -n0 * c;
    for (const Edge& e : edges_) {
      const Prediction p = predict(e.u, e.path_m, c);
      const Eigen::Vector3d r = difference(e.z, p.mean);
      const double m = std::sqrt(std::max(0.0, r.dot(e.w * r)));
      const double weight = m <= options_.huber_chi ? 1.0 : options_.huber_chi / m;
      n += weight * p.jacobian.transpose() * e.w * p.jacobian;
      g += weight * p.jacobian.transpose() * e.w * r;
    }
    const Eigen::Vector3d step = n.ldlt().solve(g);
    if (!step.allFinite()) {
      break;
    }
    c += step;
    if (step.cwiseAbs().maxCoeff() < 1e-9) {
      break;
    }
  }
  calibration_.scale = c(0);
  calibration_.turn = c(1);
  calibration_.drift_rad_per_m = c(2);
  calibration_.covariance = n.inverse();
  calibration_.edges = edges_.size();
}

Pose2 dataEstimate(const Pose2& x, const Eigen::Matrix3d& h, const Pose2& x0,
                   const Eigen::Matrix3d& l0) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(0.5 * (h + h.transpose()));
  const Eigen::Vector3d lambda = eig.eigenvalues();
  const double cut = 1e-9 * std::max(lambda(2), 0.0);
  Eigen::Vector3d inverse = Eigen::Vector3d::Zero();
  for (int i = 0; i < 3; ++i) {
    if (lambda(i) > cut && lambda(i) > 0.0) {
      inverse(i) = 1.0 / lambda(i);
    }
  }
  const Eigen::Matrix3d pinv =
      eig.eigenvectors() * inverse.asDiagonal() * eig.eigenvectors().transpose();
  const Eigen::Vector3d shift = pinv * (l0 * difference(vec(x), vec(x0)));
  return {x.x + shift(0), x.y + shift(1), wrapAngle(x.theta + shift(2))};
}

Pose2 fuse(const Pose2& z, const Eigen::Matrix3d& h, const MotionPrior& prior) {
  const Eigen::Vector3d p = vec(prior.mean);
  const Eigen::Vector3d zv = p + difference(vec(z), p);  // z's angle next to the prior's
  const Eigen::Vector3d x = (h + prior.information).ldlt().solve(h * zv + prior.information * p);
  return {x(0), x(1), wrapAngle(x(2))};
}

void OdometryEdges::add(const Term& term) {
  terms_.push_back(term);
}

void OdometryEdges::remake(const OdometryModel& model, double information_scale,
                           PoseGraph& graph) const {
  for (const Term& t : terms_) {
    const MotionPrior prior = model.prior(t.from, t.to);
    graph.setEdge(t.edge, fuse(t.data, t.data_information, prior),
                  information_scale * t.data_information + prior.information);
  }
}

}  // namespace pmap::poses
