#include "pmap/refine/plane_poses.h"

#include <ceres/ceres.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <numeric>

#include "pmap/poses/pose_graph.h"

namespace pmap::refine {
namespace {

// (P2): one point of a scan between knots k and k+1 (fraction alpha) on a
// vertical plane (angle phi, offset d).
struct PointOnPlane {
  Eigen::Vector2d p;  ///< the point, as placed (world xy)
  Eigen::Vector2d c;  ///< its scan's robot position (world xy)
  double alpha = 0;
  double inv_sigma = 1;
  template <typename T>
  bool operator()(const T* dk, const T* dk1, const T* plane, T* residual) const {
    using std::cos;
    using std::sin;
    const T a(alpha), b(1.0 - alpha);
    const T dx = b * dk[0] + a * dk1[0], dy = b * dk[1] + a * dk1[1], dth = b * dk[2] + a * dk1[2];
    const T cs = cos(dth), sn = sin(dth);
    const double ux = p.x() - c.x(), uy = p.y() - c.y();
    const T px = cs * ux - sn * uy + c.x() + dx;  // (P1)
    const T py = sn * ux + cs * uy + c.y() + dy;
    residual[0] = (cos(plane[0]) * px + sin(plane[0]) * py - plane[1]) * inv_sigma;
    return true;
  }
};

// (P3): the corrected knots keep their relative pose (the pose graph's
// edge residual between the corrected poses).
struct KnotMotion {
  poses::Pose2 from, to, z;
  Eigen::Matrix3d sqrt_information;
  template <typename T>
  bool operator()(const T* dk, const T* dk1, T* residual) const {
    const T ti[2] = {from.x + dk[0], from.y + dk[1]}, thi[1] = {from.theta + dk[2]};
    const T tj[2] = {to.x + dk1[0], to.y + dk1[1]}, thj[1] = {to.theta + dk1[2]};
    poses::edgeResidual(ti, thi, tj, thj, z, sqrt_information, residual);
    return true;
  }
};

// (P4): each knot's correction is small: the pose stage's poses hold to
// absolute_sigma_m / absolute_sigma_deg.
struct KnotPrior {
  double inv_sigma_t = 1, inv_sigma_r = 1;
  template <typename T>
  bool operator()(const T* dk, T* residual) const {
    residual[0] = dk[0] * inv_sigma_t;
    residual[1] = dk[1] * inv_sigma_t;
    residual[2] = dk[2] * inv_sigma_r;
    return true;
  }
};

poses::Pose2 pose2(const mrpt::math::TPose3D& p) {
  return {p.x, p.y, p.yaw};
}

// The scans' records in time order.
std::vector<std::size_t> timeOrder(const points::PointMap& map) {
  std::vector<std::size_t> order(map.scans().size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return map.scans()[a].timestamp < map.scans()[b].timestamp;
  });
  return order;
}

struct Knot {
  double t = 0;
  double path_m = 0;
  poses::Pose2 pose;
};

// A knot at the first scan, then every knot_spacing_m of path, and at the
// last scan.
std::vector<Knot> placeKnots(const points::PointMap& map, const std::vector<std::size_t>& order,
                             double spacing_m) {
  std::vector<Knot> knots;
  double path = 0, since = 0;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const points::ScanRecord& s = map.scans()[order[i]];
    if (i > 0) {
      const mrpt::math::TPose3D& prev = map.scans()[order[i - 1]].robot_pose;
      const double step = std::hypot(s.robot_pose.x - prev.x, s.robot_pose.y - prev.y);
      path += step;
      since += step;
    }
    const bool last = i + 1 == order.size();
    if (knots.empty() || since >= spacing_m || (last && s.timestamp > knots.back().t)) {
      knots.push_back({s.timestamp, path, pose2(s.robot_pose)});
      since = 0;
    }
  }
  return knots;
}

// The interval of sorted times `t` (at least two) holding x: (k, alpha)
// with x = (1 - alpha) t[k] + alpha t[k + 1]; alpha is held to [0, 1]
// outside the span.
std::pair<std::size_t, double> interval(const std::vector<double>& t, double x) {
  std::size_t k1 = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), x) - t.begin());
  k1 = std::clamp<std::size_t>(k1, 1, t.size() - 1);
  const double span = t[k1] - t[k1 - 1];
  const double alpha = span > 0 ? std::clamp((x - t[k1 - 1]) / span, 0.0, 1.0) : 1.0;
  return {k1 - 1, alpha};
}

Eigen::Matrix3d motionSqrtInformation(double path_m, const PlanePoseOptions& o) {
  const double st = o.motion_sigma_m_per_m * path_m + 0.005;
  const double sr = mrpt::DEG2RAD(o.motion_sigma_deg_per_m * path_m + 0.05);
  return Eigen::Vector3d(1.0 / st, 1.0 / st, 1.0 / sr).asDiagonal();
}

}  // namespace

bool PlanePoseOptions::validate(std::string* why) const {
  const double positive[] = {knot_spacing_m, sigma_m, motion_sigma_m_per_m, motion_sigma_deg_per_m,
                             huber_sigmas};
  for (const double v : positive) {
    if (!(v > 0.0) || !std::isfinite(v)) {
      *why = "plane_refine lengths, sigmas and thresholds must be finite and > 0";
      return false;
    }
  }
  if (!(absolute_sigma_m >= 0.0) || !std::isfinite(absolute_sigma_m) ||
      !(absolute_sigma_deg > 0.0) || !std::isfinite(absolute_sigma_deg)) {
    *why =
        "plane_refine_absolute_sigma_m must be >= 0 (0: none), plane_refine_absolute_sigma_deg > 0";
    return false;
  }
  if (!(max_normal_z >= 0.0 && max_normal_z < 1.0)) {
    *why = "plane_refine_max_normal_z must be in [0, 1)";
    return false;
  }
  if (points_per_scan_surface < 1 || points_per_scan_surface > 10000 || rounds < 1 || rounds > 10 ||
      max_iterations < 1 || max_iterations > 1000) {
    *why =
        "plane_refine_points_per_scan_surface must be in [1, 10000], plane_refine_rounds in "
        "[1, 10], plane_refine_max_iterations in [1, 1000]";
    return false;
  }
  return true;
}

PoseCorrection::PoseCorrection(std::vector<double> t, std::vector<Eigen::Vector3d> delta)
    : t_(std::move(t)), delta_(std::move(delta)) {}

Eigen::Vector3d PoseCorrection::at(double t) const {
  if (t_.size() < 2) {
    return t_.empty() ? Eigen::Vector3d::Zero() : delta_.front();
  }
  const auto [k, a] = interval(t_, t);
  return (1.0 - a) * delta_[k] + a * delta_[k + 1];
}

mrpt::math::TPose3D PoseCorrection::apply(double t, const mrpt::math::TPose3D& pose) const {
  const Eigen::Vector3d d = at(t);
  mrpt::math::TPose3D out = pose;
  out.x += d.x();
  out.y += d.y();
  out.yaw = mrpt::math::wrapToPi(pose.yaw + d.z());
  return out;
}

PlanePoseResult fitPosesToPlanes(const points::PointMap& map, const em::PlanarMap& planar,
                                 const PlanePoseOptions& options, const PoseCorrection& start) {
  const auto t0 = std::chrono::steady_clock::now();
  PlanePoseResult result;
  const std::vector<std::size_t> order = timeOrder(map);
  const std::vector<Knot> knots = placeKnots(map, order, options.knot_spacing_m);
  if (knots.size() < 2 || planar.assignment.size() != map.size()) {
    return result;
  }
  // The vertical surfaces: (angle, offset) of their horizontal normal.
  std::vector<std::array<double, 2>> planes(planar.surfaces.size(), {0.0, 0.0});
  std::vector<bool> vertical(planar.surfaces.size(), false);
  for (std::size_t w = 0; w < planar.surfaces.size(); ++w) {
    const em::Rectangle& r = planar.surfaces[w].rect;
    const Eigen::Vector2d n = r.normal.head<2>();
    if (std::abs(r.normal.z()) <= options.max_normal_z && n.norm() > 0) {
      vertical[w] = true;
      planes[w] = {std::atan2(n.y(), n.x()), n.normalized().dot(r.centre.head<2>())};
    }
  }
  std::vector<double> times;
  std::vector<Eigen::Vector3d> delta;
  for (const Knot& k : knots) {
    times.push_back(k.t);
    delta.push_back(start.at(k.t));
  }
  ceres::Problem problem;
  std::vector<bool> used(planar.surfaces.size(), false);
  const int m = options.points_per_scan_surface;
  for (const std::size_t rec : order) {
    const points::ScanRecord& s = map.scans()[rec];
    std::map<std::int32_t, std::vector<std::size_t>> on;  // surface -> its points in this scan
    for (std::size_t i = s.first_point; i < s.first_point + s.num_points; ++i) {
      const std::int32_t a = planar.assignment[i];
      if (a >= 0 && vertical[static_cast<std::size_t>(a)]) {
        on[a].push_back(i);
      }
    }
    const auto [k, alpha] = interval(times, s.timestamp);
    for (const auto& [w, idx] : on) {
      const std::size_t take = std::min<std::size_t>(idx.size(), static_cast<std::size_t>(m));
      for (std::size_t j = 0; j < take; ++j) {
        const Eigen::Vector3d& p = map.xyz()[idx[j * idx.size() / take]];
        auto* cost = new ceres::AutoDiffCostFunction<PointOnPlane, 1, 3, 3, 2>(
            new PointOnPlane{p.head<2>(), Eigen::Vector2d(s.robot_pose.x, s.robot_pose.y), alpha,
                             1.0 / options.sigma_m});
        problem.AddResidualBlock(cost, new ceres::HuberLoss(options.huber_sigmas), delta[k].data(),
                                 delta[k + 1].data(), planes[static_cast<std::size_t>(w)].data());
        ++result.residuals;
      }
      used[static_cast<std::size_t>(w)] = true;
    }
  }
  if (result.residuals == 0) {
    return result;
  }
  for (std::size_t k = 0; k + 1 < knots.size(); ++k) {
    KnotMotion motion{knots[k].pose, knots[k + 1].pose,
                      poses::between(knots[k].pose, knots[k + 1].pose),
                      motionSqrtInformation(knots[k + 1].path_m - knots[k].path_m, options)};
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<KnotMotion, 3, 3, 3>(new KnotMotion(motion)), nullptr,
        delta[k].data(), delta[k + 1].data());
  }
  problem.SetParameterBlockConstant(delta[0].data());  // the gauge (start's first knot)
  if (options.absolute_sigma_m > 0) {
    for (std::size_t k = 1; k < knots.size(); ++k) {
      problem.AddResidualBlock(
          new ceres::AutoDiffCostFunction<KnotPrior, 3, 3>(new KnotPrior{
              1.0 / options.absolute_sigma_m, 1.0 / mrpt::DEG2RAD(options.absolute_sigma_deg)}),
          nullptr, delta[k].data());
    }
  }
  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  solver.max_num_iterations = options.max_iterations;
  solver.num_threads = 1;
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
  if (summary.termination_type == ceres::FAILURE) {
    result.termination = "FAILURE: " + summary.message;
    return result;
  }
  for (std::size_t k = 0; k < knots.size(); ++k) {
    result.max_shift_m = std::max(result.max_shift_m, delta[k].head<2>().norm());
    result.max_turn_deg = std::max(result.max_turn_deg, mrpt::RAD2DEG(std::abs(delta[k].z())));
  }
  result.ran = true;
  result.correction = PoseCorrection(std::move(times), std::move(delta));
  result.knots = static_cast<int>(knots.size());
  result.surfaces = static_cast<int>(std::count(used.begin(), used.end(), true));
  result.iterations = static_cast<int>(summary.iterations.size());
  result.initial_cost = summary.initial_cost;
  result.final_cost = summary.final_cost;
  result.termination = ceres::TerminationTypeToString(summary.termination_type);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

void applyCorrection(const PoseCorrection& correction, points::PointMap& map,
                     poses::Trajectory& trajectory) {
  for (std::size_t i = 0; i < map.scans().size(); ++i) {
    const points::ScanRecord& s = map.scans()[i];
    map.moveScan(i, correction.apply(s.timestamp, s.robot_pose));
  }
  poses::Trajectory moved;
  for (const poses::TimedPose& p : trajectory.poses()) {
    moved.append(p.t, correction.apply(p.t, p.pose));
  }
  trajectory = std::move(moved);
}

}  // namespace pmap::refine
