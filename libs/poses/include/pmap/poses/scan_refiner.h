// Point-to-line refinement of a relative pose (doc/poses.md, "Keyframe
// edges"): a scan's points against a local map of earlier scans whose
// surfaces are lines (each reference point with the normal of the line
// through its neighbours along its scan, as Censi's PL-ICP), started from the front end's estimate
// and held to it by that estimate's information (the prior), so that directions the scene does not
// constrain (a corridor's axis) stay where the front end put them.
//
// For the pose x = (t, theta) of the scan in the map's frame, each query
// point p_i matched to its nearest reference point q_i (normal n_i) gives
//   r_i(x) = n_i . (R(theta) p_i + t - q_i) / sigma,
// and the estimate minimises
//   sum_i huber(r_i)^2 + (x - x0)^T L0 (x - x0),     (Gauss-Newton, IRLS)
// x0 the front end's pose and L0 its information. The pose's information
// is the Gauss-Newton Hessian at the solution,
//   L = information_scale * sum_i w_i J_i^T J_i / sigma^2 + L0,
// J_i = [n_i^T, n_i^T R'(theta) p_i]: tight across walls, nothing along a
// corridor beyond the prior. information_scale < 1 accounts for the points'
// errors not being independent (neighbouring beams share the surface's
// roughness and the map's own pose errors). The solve itself weighs the
// points in full against the prior (deliberately not the same model as the
// information handed on: the estimate is the points' where they say
// something; the scale only keeps the chain of edges from being too stiff
// for the loops, doc/poses.md). Measured, not derived: a solve weighted
// like the information was not tried.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "pmap/poses/free_space.h"
#include "pmap/poses/pose_graph.h"

namespace pmap::poses {

struct ScanRefineOptions {
  double sigma_m = 0.03;        ///< a point's distance-to-line noise (m)
  double max_distance_m = 0.3;  ///< a query point's match must be this close (m)
  /// A reference point's normal: the line through it and its neighbours
  /// along its scan, up to normal_half_width on each side, while
  /// consecutive ones are closer than max_gap_m (one surface).
  int normal_half_width = 2;
  double max_gap_m = 0.5;
  /// A neighbourhood is a line when its smaller principal spread is at most
  /// this fraction of its larger one (sqrt of the eigenvalue ratio): not a
  /// corner, and not beams so close together that the range noise hides
  /// the line's direction.
  double max_thickness = 0.25;
  /// When the neighbourhood on both sides is no line (a corner), the side
  /// of the point that is one gives its normal, if only one is: the end of
  /// a line, such as a door's jamb seen by a few beams before the wall.
  bool one_sided_normals = true;
  double huber_sigmas = 2.0;  ///< residuals beyond this many sigma weigh less (Huber)
  int max_iterations = 20;
  /// Of the points' information, the share that is taken as independent.
  double information_scale = 0.03;
  /// Fewer matched points than this: no refinement (the prior is returned).
  int min_matches = 30;
  bool validate(std::string* why) const;
};

/// Reference points with the normals of their neighbourhoods, hashed on a
/// grid for nearest-point look-ups.
class LineMap {
 public:
  /// `scans`: the reference scans in one frame, their points in beam order.
  LineMap(const std::vector<Rays>& scans, const ScanRefineOptions& options);

  /// The reference point nearest to `p` within max_distance_m that has a
  /// normal; false when there is none.
  bool nearest(const Eigen::Vector2d& p, Eigen::Vector2d* point, Eigen::Vector2d* normal) const;
  std::size_t size() const { return points_.size(); }

 private:
  std::int64_t key(int cx, int cy) const;
  int cellOf(double v) const;

  double cell_m_;
  double max_distance_m_;
  std::vector<Eigen::Vector2d> points_;   ///< those with a normal
  std::vector<Eigen::Vector2d> normals_;  ///< unit
  std::unordered_map<std::int64_t, std::vector<std::size_t>> cells_;
};

struct RefinedPose {
  bool refined = false;  ///< false: too few matches, the prior is returned
  Pose2 pose;
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();  ///< (x, y, theta)
  /// The points' own Gauss-Newton Hessian at the pose (sum w J^T J /
  /// sigma^2, unscaled, no prior); zero when not refined.
  Eigen::Matrix3d data_information = Eigen::Matrix3d::Zero();
  int matches = 0;
  int iterations = 0;
};

/// The flat prior of a match (1 m, 5 deg): enough to keep Gauss-Newton
/// well-posed along a corridor, taken out of the result again
/// (dataEstimate, odometry_model.h).
Eigen::Matrix3d flatPrior();

/// `information` without the direction `direction` (unit): (I - d d^T)
/// L (I - d d^T), nothing along it, the rest unchanged.
Eigen::Matrix3d withoutDirection(const Eigen::Matrix3d& information,
                                 const Eigen::Vector3d& direction);

/// The translation the points constrain least: the eigenvector (x, y, 0)
/// of the information's translation block with the smaller eigenvalue, and
/// that eigenvalue's ratio to the larger one (0 when the block is zero).
/// Along a bare corridor it is the axis, whose information comes only from
/// the normals' noise (a ratio about 1e-4, the walls across several 1e5).
struct WeakestTranslation {
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();
  double ratio = 0.0;
};
WeakestTranslation weakestTranslation(const Eigen::Matrix3d& information);

/// The pose of the scan `query` (points in its own frame) in `map`'s frame,
/// started from `guess`, held to `prior_mean` with information `prior`
/// (symmetric positive definite). Deterministic.
RefinedPose refinePose(const LineMap& map, const std::vector<Eigen::Vector2d>& query,
                       const Pose2& guess, const Pose2& prior_mean, const Eigen::Matrix3d& prior,
                       const ScanRefineOptions& options);

/// The same with the prior centred on the start.
RefinedPose refinePose(const LineMap& map, const std::vector<Eigen::Vector2d>& query,
                       const Pose2& guess, const Eigen::Matrix3d& prior,
                       const ScanRefineOptions& options);

}  // namespace pmap::poses
