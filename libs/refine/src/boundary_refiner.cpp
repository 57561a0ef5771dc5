#include "pmap/refine/boundary_refiner.h"

#include <ceres/ceres.h>

#include <cmath>

#include "pmap/refine/cost_functions.h"
#include "pmap/refine/surface_params.h"

namespace pmap::refine {
namespace {

constexpr double kDegToRad = M_PI / 180.0;
constexpr int kMaxPasses = 3;  ///< solves: the first, then with refused surfaces held

class Problem {
 public:
  Problem(std::vector<SurfaceParams>& params, const RefineOptions& options)
      : params_(params), options_(options) {
    for (SurfaceParams& p : params_) {
      problem_.AddParameterBlock(p.normal.data(), 3, new ceres::SphereManifold<3>());
      problem_.AddParameterBlock(&p.offset, 1);
      problem_.AddParameterBlock(&p.rotation, 1);
      problem_.AddParameterBlock(p.bounds.data(), 4);
    }
  }

  // The plane part of eq. (5) over all of surface j's measurements,
  // weighted by e_ij (the M-step's moments, eqs. 24-27).
  void addPlane(std::size_t j, const std::vector<Eigen::Vector3d>& points,
                const std::vector<SurfaceSample>& samples, double sigma_m) {
    if (samples.empty()) {
      return;
    }
    SurfaceParams& p = params_[j];
    double w = 0;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const SurfaceSample& s : samples) {
      w += s.weight;
      sum += s.weight * (points[static_cast<std::size_t>(s.point)] - p.ref_centre);
    }
    const Eigen::Vector3d mean = sum / w;
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const SurfaceSample& s : samples) {
      const Eigen::Vector3d d = points[static_cast<std::size_t>(s.point)] - p.ref_centre - mean;
      scatter += s.weight * d * d.transpose();
    }
    auto* cost = new ceres::AutoDiffCostFunction<PlaneFromMoments, 4, 3, 1>(
        new PlaneFromMoments(scatter, p.ref_centre + mean, w, sigma_m));
    problem_.AddResidualBlock(cost, nullptr, p.normal.data(), &p.offset);
  }

  // The in-plane part of eq. (5) for the members within the EM's rectangle
  // and near its boundary (the others cannot leave it), an even subsample
  // of at most max_points_per_surface, each weighted by e_ij times (band
  // weight / subsample weight), under a Huber loss. They keep an edge from
  // cutting into its points; members the EM's rectangle fit left outside
  // (eq. 29 with coherent members) do not pull it out.
  void addBoundary(std::size_t j, const std::vector<Eigen::Vector3d>& points,
                   const std::vector<SurfaceSample>& samples, double sigma_m) {
    SurfaceParams& p = params_[j];
    const em::Rectangle r = p.toRectangle();
    const double band = options_.seam_distance_m;
    std::vector<SurfaceSample> near;
    for (const SurfaceSample& s : samples) {
      const Eigen::Vector3d d = points[static_cast<std::size_t>(s.point)] - r.centre;
      const double u = std::abs(r.axis_u.dot(d));
      const double v = std::abs(r.axisV().dot(d));
      if (s.member && u <= r.half_u && v <= r.half_v &&
          (u > r.half_u - band || v > r.half_v - band)) {
        near.push_back(s);
      }
    }
    if (near.empty()) {
      return;
    }
    const std::size_t cap = static_cast<std::size_t>(options_.max_points_per_surface);
    const std::size_t stride = (near.size() + cap - 1) / cap;
    double all = 0, used = 0;
    for (std::size_t k = 0; k < near.size(); ++k) {
      all += near[k].weight;
      used += k % stride == 0 ? near[k].weight : 0.0;
    }
    for (std::size_t k = 0; k < near.size(); k += stride) {
      auto* loss = new ceres::ScaledLoss(new ceres::HuberLoss(options_.robust_loss_sigmas),
                                         near[k].weight * all / used, ceres::TAKE_OWNERSHIP);
      auto* cost = new ceres::AutoDiffCostFunction<BeyondBounds, 2, 3, 1, 1, 4>(new BeyondBounds(
          points[static_cast<std::size_t>(near[k].point)], p.ref_centre, p.ref_axis, sigma_m));
      problem_.AddResidualBlock(cost, loss, p.normal.data(), &p.offset, &p.rotation,
                                p.bounds.data());
    }
  }

  void addExtentPrior(std::size_t j) {
    SurfaceParams& p = params_[j];
    auto* cost = new ceres::AutoDiffCostFunction<ExtentPrior, 5, 1, 4>(
        new ExtentPrior(p, options_.extent_sigma_m, options_.rotation_sigma_deg * kDegToRad));
    problem_.AddResidualBlock(cost, nullptr, &p.rotation, p.bounds.data());
  }

  void addSeam(const Seam& s) {
    SurfaceParams& a = params_[s.surface];
    SurfaceParams& b = params_[s.other];
    auto* cost = new ceres::AutoDiffCostFunction<EdgeOnPlane, 2, 3, 1, 1, 4, 3, 1>(
        new EdgeOnPlane(s.edge, s.along, a.ref_centre, a.ref_axis, options_.seam_sigma_m));
    // Cauchy: a seam the data cannot close within about seam_give_up_m
    // (a wrong one, between surfaces that do not meet) stops pulling.
    auto* loss = new ceres::CauchyLoss(options_.seam_give_up_m / options_.seam_sigma_m);
    problem_.AddResidualBlock(cost, loss, a.normal.data(), &a.offset, &a.rotation, a.bounds.data(),
                              b.normal.data(), &b.offset);
  }

  // Manhattan prior between every pair within the tolerance of parallel or
  // orthogonal; marks the surfaces it ties, returns how many pairs.
  std::size_t addManhattan(std::vector<char>& tied) {
    const double tol = std::sin(options_.manhattan_tolerance_deg * kDegToRad);
    std::size_t pairs = 0;
    for (std::size_t a = 0; a < params_.size(); ++a) {
      for (std::size_t b = a + 1; b < params_.size(); ++b) {
        const Eigen::Vector3d na = params_[a].normalVector();
        const Eigen::Vector3d nb = params_[b].normalVector();
        const bool orthogonal = std::abs(na.dot(nb)) < tol;
        if (!orthogonal && na.cross(nb).norm() >= tol) {
          continue;
        }
        auto* cost = new ceres::AutoDiffCostFunction<ManhattanPrior, 3, 3, 3>(
            new ManhattanPrior(orthogonal, options_.manhattan_sigma_deg * kDegToRad));
        problem_.AddResidualBlock(cost, nullptr, params_[a].normal.data(),
                                  params_[b].normal.data());
        tied[a] = tied[b] = 1;
        ++pairs;
      }
    }
    return pairs;
  }

  /// Surface j keeps its EM plane (nothing ties it to another surface).
  void holdPlane(std::size_t j) {
    problem_.SetParameterBlockConstant(params_[j].normal.data());
    problem_.SetParameterBlockConstant(&params_[j].offset);
  }

  /// Surface j keeps the EM's in-plane orientation.
  void holdRotation(std::size_t j) { problem_.SetParameterBlockConstant(&params_[j].rotation); }

  /// Surface j keeps its EM rectangle in its plane (none of its edges ends
  /// on a seam).
  void holdRectangle(std::size_t j) {
    problem_.SetParameterBlockConstant(&params_[j].rotation);
    problem_.SetParameterBlockConstant(params_[j].bounds.data());
  }

  ceres::Solver::Summary solve() {
    ceres::Solver::Options o;
    o.max_num_iterations = options_.max_iterations;
    o.linear_solver_type =
        ceres::IsSparseLinearAlgebraLibraryTypeAvailable(ceres::EIGEN_SPARSE) ||
                ceres::IsSparseLinearAlgebraLibraryTypeAvailable(ceres::SUITE_SPARSE)
            ? ceres::SPARSE_NORMAL_CHOLESKY
            : ceres::DENSE_QR;
    o.num_threads = 1;
    o.logging_type = ceres::SILENT;
    ceres::Solver::Summary summary;
    ceres::Solve(o, &problem_, &summary);
    return summary;
  }

 private:
  std::vector<SurfaceParams>& params_;
  const RefineOptions& options_;
  ceres::Problem problem_;
};

// The refined surface, or false when it must keep the EM's geometry.
bool acceptRefined(const em::Rectangle& before, const SurfaceParams& p, double max_turn_deg,
                   em::Rectangle& out) {
  out = p.toRectangle();
  const double turn = std::acos(std::min(1.0, std::abs(before.normal.dot(out.normal)))) / kDegToRad;
  const bool finite = out.centre.allFinite() && out.normal.allFinite() && out.axis_u.allFinite();
  return finite && turn <= max_turn_deg && p.bounds[kUMax] > p.bounds[kUMin] &&
         p.bounds[kVMax] > p.bounds[kVMin];
}

// One solve of all surfaces from `params` (in place); surfaces marked in
// `held` keep their plane and rectangle. Records the seams' Manhattan pairs.
ceres::Solver::Summary solveOnce(const std::vector<Eigen::Vector3d>& points,
                                 const std::vector<std::vector<SurfaceSample>>& samples,
                                 double sigma_m, const RefineOptions& options,
                                 const std::vector<char>& held, BoundaryResult& result,
                                 std::vector<SurfaceParams>& params) {
  Problem problem(params, options);
  for (std::size_t j = 0; j < params.size() && j < samples.size(); ++j) {
    problem.addPlane(j, points, samples[j], sigma_m);
    problem.addBoundary(j, points, samples[j], sigma_m);
    problem.addExtentPrior(j);
  }
  std::vector<char> tied(params.size(), 0);
  std::vector<char> has_seam_edge(params.size(), 0);
  for (const Seam& s : result.seams) {
    problem.addSeam(s);
    tied[s.surface] = tied[s.other] = 1;
    has_seam_edge[s.surface] = 1;
  }
  if (options.manhattan) {
    result.manhattan_pairs = problem.addManhattan(tied);
  }
  for (std::size_t j = 0; j < params.size(); ++j) {
    if (!tied[j] || held[j]) {
      problem.holdPlane(j);
    }
    if (!has_seam_edge[j] || held[j]) {
      problem.holdRectangle(j);
    } else if (!options.free_rotation) {
      problem.holdRotation(j);
    }
  }
  return problem.solve();
}

}  // namespace

std::vector<std::vector<SurfaceSample>> samplesFromResponsibilities(
    const em::Responsibilities& resp, std::size_t surfaces, double min_weight) {
  std::vector<std::vector<SurfaceSample>> samples(surfaces);
  for (std::size_t i = 0; i < resp.points(); ++i) {
    for (std::uint32_t k = resp.offsets[i]; k < resp.offsets[i + 1]; ++k) {
      const auto j = static_cast<std::size_t>(resp.surface[k]);
      if (j < surfaces && resp.weight[k] >= min_weight) {
        samples[j].push_back(
            {static_cast<std::int32_t>(i), resp.weight[k], resp.best[i] == resp.surface[k]});
      }
    }
  }
  return samples;
}

BoundaryResult refineBoundaries(const std::vector<Eigen::Vector3d>& points,
                                const std::vector<std::vector<SurfaceSample>>& samples,
                                double sigma_m, const RefineOptions& options,
                                std::vector<em::Surface>& surfaces) {
  BoundaryResult result;
  std::vector<SurfaceParams> params;
  for (const em::Surface& s : surfaces) {
    params.push_back(SurfaceParams::fromRectangle(s.rect));
  }
  result.seams = findSeams(params, options);
  if (surfaces.empty() || (result.seams.empty() && !options.manhattan)) {
    result.termination = "nothing to refine";
    return result;
  }
  std::vector<char> held(surfaces.size(), 0);
  std::vector<SurfaceParams> solved;
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    solved = params;
    const ceres::Solver::Summary summary =
        solveOnce(points, samples, sigma_m, options, held, result, solved);
    result.termination = ceres::TerminationTypeToString(summary.termination_type);
    result.iterations += static_cast<int>(summary.iterations.size());
    if (pass == 0) {
      result.initial_cost = summary.initial_cost;
    }
    result.final_cost = summary.final_cost;
    if (summary.termination_type == ceres::FAILURE) {
      return result;
    }
    // Surfaces the solve would turn too far or collapse keep the EM's
    // geometry; solved again with them held, their neighbours adapt to it.
    bool any = false;
    for (std::size_t j = 0; j < surfaces.size(); ++j) {
      em::Rectangle refined;
      if (!held[j] &&
          !acceptRefined(surfaces[j].rect, solved[j], options.max_normal_change_deg, refined)) {
        held[j] = 1;
        any = true;
      }
    }
    if (!any) {
      break;
    }
  }
  for (std::size_t j = 0; j < surfaces.size(); ++j) {
    em::Rectangle refined;
    if (!held[j] &&
        acceptRefined(surfaces[j].rect, solved[j], options.max_normal_change_deg, refined)) {
      surfaces[j].rect = refined;
    } else {
      result.reverted_ids.push_back(surfaces[j].id);
    }
  }
  return result;
}

}  // namespace pmap::refine
