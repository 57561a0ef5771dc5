#include "pmap/poses/path_constraints.h"

#include <cmath>

#include "pmap/poses/free_space.h"
#include "pmap/poses/odometry_model.h"

namespace pmap::poses {
namespace {

// The information of a match with nothing left along the line between the
// two keyframes when the points hardly see that direction: less than
// min_along_ratio of the information across it (the degenerate direction
// of Zhang, Kaess and Singh, ICRA 2016). Along a bare corridor the points
// say nothing along the axis, but noisy normals make up a little
// information there (measured:
// a bare 40 m corridor driven there and back ended 0.19 m off with it
// kept, the test's bound being 0.15 m; its matches have 1e-5 of the cross
// information along at the median, the loop world's 0.16, with doors). The
// chain's calibrated odometry has that direction; a trace of the flat prior
// (added by the caller) keeps the information positive definite.
Eigen::Matrix3d degenerateAlongTrackRemoved(const Eigen::Matrix3d& information, const Pose2& motion,
                                            double min_along_ratio) {
  const double d = std::hypot(motion.x, motion.y);
  if (!(d > 0.0)) {
    return information;
  }
  const Eigen::Vector3d along(motion.x / d, motion.y / d, 0.0);
  const Eigen::Vector3d across(-along.y(), along.x(), 0.0);
  if (along.dot(information * along) >= min_along_ratio * across.dot(information * across)) {
    return information;
  }
  return withoutDirection(information, along);
}

}  // namespace

bool PathConstraintOptions::validate(std::string* why) const {
  if (count < 0 || count > 20) {
    *why = "path_constraints must be in [0, 20]";
    return false;
  }
  if (!(min_along_ratio >= 0.0 && min_along_ratio <= 1.0)) {
    *why = "path_constraint_min_along_ratio must be in [0, 1]";
    return false;
  }
  const double positive[] = {spacing_m, submap_half_path_m, max_chi2, max_gap_m};
  for (const double v : positive) {
    if (!(v > 0.0) || !std::isfinite(v)) {
      *why =
          "path_constraint_spacing_m, path_constraint_submap_m, path_constraint_max_chi2 and "
          "path_constraint_max_gap_m must be finite and > 0";
      return false;
    }
  }
  return true;
}

PathConstraints::PathConstraints(PathConstraintOptions options, ScanRefineOptions refine)
    : options_(options), refine_(refine) {}

const LineMap& PathConstraints::submap(std::size_t centre, const std::vector<Keyframe>& keyframes,
                                       const PoseGraph& graph) {
  const auto found = submaps_.find(centre);
  if (found != submaps_.end()) {
    return found->second;
  }
  std::vector<Rays> scans;
  const double at = keyframes[centre].path_m;
  for (std::size_t i = centre + 1;
       i-- > 0 && at - keyframes[i].path_m <= options_.submap_half_path_m;) {
    scans.push_back(moved({Rays{Eigen::Vector2d::Zero(), keyframes[i].points}},
                          between(graph.node(centre), graph.node(i)))
                        .front());
  }
  for (std::size_t i = centre + 1;
       i < keyframes.size() && keyframes[i].path_m - at <= options_.submap_half_path_m; ++i) {
    scans.push_back(moved({Rays{Eigen::Vector2d::Zero(), keyframes[i].points}},
                          between(graph.node(centre), graph.node(i)))
                        .front());
  }
  ScanRefineOptions lines = refine_;
  lines.max_gap_m = options_.max_gap_m;
  return submaps_.emplace(centre, LineMap(scans, lines)).first->second;
}

void PathConstraints::add(std::size_t id, const std::vector<Keyframe>& keyframes,
                          const PoseGraph& graph) {
  const Keyframe& k = keyframes[id];
  // Submaps no later keyframe reaches back to are not needed again.
  const double oldest = k.path_m - options_.count * options_.spacing_m - options_.spacing_m;
  while (!submaps_.empty() && keyframes[submaps_.begin()->first].path_m < oldest) {
    submaps_.erase(submaps_.begin());
  }
  const Eigen::Matrix3d flat = flatPrior();
  std::size_t j = id;
  for (int n = 1; n <= options_.count; ++n) {
    const double target = k.path_m - n * options_.spacing_m;
    while (j > 0 && keyframes[j].path_m > target) {
      --j;
    }
    // Its submap must not reach the keyframe matched against it.
    if (keyframes[j].path_m > target ||
        k.path_m - keyframes[j].path_m <= 2.0 * options_.submap_half_path_m) {
      break;
    }
    const Pose2 guess = between(graph.node(j), graph.node(id));
    const RefinedPose r = refinePose(submap(j, keyframes, graph), k.points, guess, flat, refine_);
    if (!r.refined) {
      continue;
    }
    PoseEdge e;
    e.from = j;
    e.to = id;
    e.measurement = dataEstimate(r.pose, r.data_information, guess, flat);
    e.information =
        refine_.information_scale *
            degenerateAlongTrackRemoved(r.data_information, guess, options_.min_along_ratio) +
        1e-3 * flat;
    e.loop = true;
    e.path = true;
    if (graph.chi2(e) > options_.max_chi2) {
      ++rejected_;
      continue;
    }
    edges_.push_back(e);
  }
}

}  // namespace pmap::poses
