#include "pmap/em/noise_estimate.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <unordered_map>

#include "pmap/em/cell_key.h"
#include "pmap/em/planar_em_options.h"
#include "pmap/em/point_grid.h"

namespace pmap::em {
namespace {

// A grid cell holding, on average over occupied cells, at least k / 8
// points: the k nearest of a point then lie within a few cells of it.
double cellFor(const std::vector<Eigen::Vector3d>& points, int k) {
  double cell = 0.02;
  for (int round = 0; round < 30; ++round, cell *= 2.0) {
    std::unordered_map<std::int64_t, int> counts;
    for (const Eigen::Vector3d& p : points) {
      ++counts[cellKeyOf(p, cell)];
    }
    if (static_cast<double>(points.size()) >= counts.size() * (k / 8.0)) {
      break;
    }
  }
  return cell;
}

// The root of the smallest eigenvalue of the covariance of the k points of
// `points` nearest to points[i].
double thickness(const std::vector<Eigen::Vector3d>& points, const PointGrid& grid, std::size_t i,
                 int k) {
  const Eigen::Vector3d& p = points[i];
  std::vector<std::int32_t> near;
  for (double r = grid.cell(); near.size() < static_cast<std::size_t>(k); r *= 2.0) {
    near = grid.within(p, r);
  }
  std::vector<std::pair<double, std::int32_t>> by_distance;
  by_distance.reserve(near.size());
  for (const std::int32_t j : near) {
    by_distance.emplace_back((points[static_cast<std::size_t>(j)] - p).squaredNorm(), j);
  }
  std::nth_element(by_distance.begin(), by_distance.begin() + (k - 1), by_distance.end());
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int n = 0; n < k; ++n) {
    mean += points[static_cast<std::size_t>(by_distance[static_cast<std::size_t>(n)].second)];
  }
  mean /= k;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (int n = 0; n < k; ++n) {
    const Eigen::Vector3d d =
        points[static_cast<std::size_t>(by_distance[static_cast<std::size_t>(n)].second)] - mean;
    cov += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov / k, Eigen::EigenvaluesOnly);
  return std::sqrt(std::max(0.0, eig.eigenvalues()(0)));
}

double quantile(std::vector<double> v, double q) {
  const auto at = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(at), v.end());
  return v[at];
}

}  // namespace

bool NoiseEstimateOptions::validate(std::string* why) const {
  if (samples < 1 || neighbours < 3 || !(floor_m >= 0.0) || !std::isfinite(floor_m)) {
    *why = "noise estimate: samples >= 1, neighbours >= 3, floor_m >= 0";
    return false;
  }
  return true;
}

NoiseEstimate estimateRangeSigma(const std::vector<Eigen::Vector3d>& points,
                                 const NoiseEstimateOptions& options) {
  NoiseEstimate out;
  const int k = options.neighbours;
  if (points.size() < static_cast<std::size_t>(k) + 1) {
    return out;
  }
  // The sample: a seeded shuffle's first `samples` indices (all when fewer).
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::mt19937_64 rng(options.seed);
  const std::size_t n = std::min(order.size(), static_cast<std::size_t>(options.samples));
  for (std::size_t i = 0; i < n; ++i) {  // partial Fisher-Yates
    std::uniform_int_distribution<std::size_t> pick(i, order.size() - 1);
    std::swap(order[i], order[pick(rng)]);
  }
  const PointGrid grid(points, cellFor(points, k));
  std::vector<double> values;
  values.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    values.push_back(thickness(points, grid, order[i], k));
  }
  out.estimated = true;
  out.samples = static_cast<int>(n);
  out.sigma_m = std::max(options.floor_m, quantile(values, 0.5));
  out.p25_m = quantile(values, 0.25);
  out.p75_m = quantile(values, 0.75);
  return out;
}

NoiseEstimate estimateSigmaInto(PlanarEmOptions& options,
                                const std::vector<Eigen::Vector3d>& points) {
  NoiseEstimate e = estimateRangeSigma(points);
  PlanarEmOptions tried = options;
  tried.sigma_m = e.sigma_m;
  std::string why;
  if (e.estimated && tried.validate(&why)) {
    options.sigma_m = e.sigma_m;
  } else {
    e.estimated = false;
  }
  return e;
}

}  // namespace pmap::em
