#include "pmap/eval/plane_detection.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

namespace pmap::eval {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// n.x = d with the sign fixed so that the largest |component| of n is
/// positive: coplanar rectangles facing opposite ways get the same plane.
Eigen::Vector4d canonicalPlane(Eigen::Vector3d n, double d) {
  n.normalize();
  int k = 0;
  n.cwiseAbs().maxCoeff(&k);
  if (n[k] < 0) {
    n = -n;
    d = -d;
  }
  return Eigen::Vector4d(n.x(), n.y(), n.z(), d);
}

Eigen::Vector3d rectangleNormal(const GtRectangle& r) {
  const Eigen::Vector3d n = (r.corners[1] - r.corners[0]).cross(r.corners[3] - r.corners[0]);
  return n.norm() > 0 ? n.normalized() : r.normal;
}

/// Face k of a box (0-5: -x, +x, -y, +y, -z, +z of its frame) as a world plane.
Eigen::Vector4d boxFace(const GtBox& b, int k) {
  const int axis = k / 2;
  Eigen::Vector3d local = Eigen::Vector3d::Zero();
  local[axis] = 1.0;
  const double along = k % 2 == 0 ? b.min[axis] : b.max[axis];
  const double c = std::cos(b.yaw);
  const double s = std::sin(b.yaw);
  const Eigen::Vector3d n(c * local.x() - s * local.y(), s * local.x() + c * local.y(), local.z());
  const Eigen::Vector3d centre(b.centre.x(), b.centre.y(), 0.0);
  return canonicalPlane(n, n.dot(centre) + along);
}

/// The face of box b nearest to p (in the box's frame).
int nearestFace(const GtBox& b, const Eigen::Vector3d& p) {
  const Eigen::Vector3d q = b.local(p);
  int best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 6; ++k) {
    const int axis = k / 2;
    const double d = std::abs(q[axis] - (k % 2 == 0 ? b.min[axis] : b.max[axis]));
    if (d < best_d) {
      best_d = d;
      best = k;
    }
  }
  return best;
}

int findRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

}  // namespace

bool GtPlaneOptions::validate(std::string* why) const {
  if (!(coplanar_deg >= 0 && coplanar_deg < 90) ||
      !(coplanar_m >= 0 && std::isfinite(coplanar_m))) {
    *why = "coplanar_deg must be in [0, 90) and coplanar_m finite and >= 0";
    return false;
  }
  return true;
}

bool PlaneScoreOptions::validate(std::string* why) const {
  if (!(min_share > 0 && min_share <= 1) || !(max_angle_deg > 0 && max_angle_deg <= 90)) {
    *why = "min_share must be in (0, 1] and max_angle_deg in (0, 90]";
    return false;
  }
  return true;
}

GtPlanes groundTruthPlanes(const GroundTruth& gt, const std::vector<Eigen::Vector3d>& points,
                           const std::vector<int>& labels, const GtPlaneOptions& options) {
  std::string why;
  if (!options.validate(&why) || points.size() != labels.size()) {
    throw std::invalid_argument(why.empty() ? "points and labels differ in size" : why);
  }
  // Candidate planes: one per rectangle, six per box; then coplanar ones merged.
  std::vector<Eigen::Vector4d> candidates;
  std::vector<std::string> kinds;
  std::unordered_map<int, int> rectangle_candidate;
  std::unordered_map<int, int> first_face;  // box id -> its face 0's candidate
  for (const auto& r : gt.surfaces) {
    rectangle_candidate[r.id] = static_cast<int>(candidates.size());
    const Eigen::Vector3d n = rectangleNormal(r);
    candidates.push_back(canonicalPlane(n, n.dot(r.corners[0])));
    kinds.push_back(r.kind);
  }
  for (const auto& b : gt.boxes) {
    first_face[b.id] = static_cast<int>(candidates.size());
    for (int k = 0; k < 6; ++k) {
      candidates.push_back(boxFace(b, k));
      kinds.push_back(b.kind + " face");
    }
  }
  const double cos_max = std::cos(options.coplanar_deg * kPi / 180.0);
  std::vector<int> parent(candidates.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      const bool parallel = candidates[i].head<3>().dot(candidates[j].head<3>()) >= cos_max;
      if (parallel && std::abs(candidates[i][3] - candidates[j][3]) <= options.coplanar_m) {
        parent[findRoot(parent, static_cast<int>(i))] = findRoot(parent, static_cast<int>(j));
      }
    }
  }
  GtPlanes out;
  std::unordered_map<int, int> plane_of_root;
  const auto planeOf = [&](int candidate) {
    const int root = findRoot(parent, candidate);
    const auto [it, added] = plane_of_root.emplace(root, static_cast<int>(out.planes.size()));
    if (added) {
      out.planes.push_back(candidates[root]);
      out.kinds.push_back(kinds[root]);
    }
    return it->second;
  };
  std::unordered_map<int, int> wall_of_poster;
  for (const auto& p : gt.posters) {
    wall_of_poster[p.id] = p.wall_id;
  }
  std::unordered_map<int, const GtBox*> box_by_id;
  for (const auto& b : gt.boxes) {
    box_by_id[b.id] = &b;
  }
  out.plane_of_point.assign(points.size(), kNoPlane);
  for (std::size_t i = 0; i < points.size(); ++i) {
    int id = labels[i];
    if (const auto w = wall_of_poster.find(id); w != wall_of_poster.end()) {
      id = w->second;
    }
    if (const auto r = rectangle_candidate.find(id); r != rectangle_candidate.end()) {
      out.plane_of_point[i] = planeOf(r->second);
    } else if (const auto b = box_by_id.find(id); b != box_by_id.end()) {
      out.plane_of_point[i] = planeOf(first_face[id] + nearestFace(*b->second, points[i]));
    }
  }
  return out;
}

Eigen::Vector3d fittedNormal(const std::vector<Eigen::Vector3d>& points,
                             const std::vector<int>& indices) {
  if (indices.size() < 3) {
    return Eigen::Vector3d::Zero();
  }
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const int i : indices) {
    mean += points[static_cast<std::size_t>(i)];
  }
  mean /= static_cast<double>(indices.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const int i : indices) {
    const Eigen::Vector3d d = points[static_cast<std::size_t>(i)] - mean;
    cov += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  return eig.eigenvectors().col(0);  // eigenvalues ascend
}

PlaneScore scorePlanes(const std::vector<Eigen::Vector3d>& points,
                       const std::vector<int>& plane_of_point,
                       const std::vector<std::vector<int>>& detections,
                       const PlaneScoreOptions& options) {
  std::string why;
  if (!options.validate(&why)) {
    throw std::invalid_argument(why);
  }
  if (points.size() != plane_of_point.size()) {
    throw std::invalid_argument("points and plane labels differ in size");
  }
  std::unordered_map<int, std::vector<int>> members;  // ground-truth plane -> its points
  for (std::size_t i = 0; i < plane_of_point.size(); ++i) {
    if (plane_of_point[i] != kNoPlane) {
      members[plane_of_point[i]].push_back(static_cast<int>(i));
    }
  }
  std::unordered_map<int, Eigen::Vector3d> gt_normal;
  const auto normalOf = [&](int plane) {
    auto it = gt_normal.find(plane);
    if (it == gt_normal.end()) {
      it = gt_normal.emplace(plane, fittedNormal(points, members[plane])).first;
    }
    return it->second;
  };
  const double cos_max = std::cos(options.max_angle_deg * kPi / 180.0);
  std::unordered_map<int, std::size_t> matches_of;  // ground-truth plane -> matching detections
  PlaneScore s;
  for (const auto& d : detections) {
    for (const int i : d) {
      if (i < 0 || static_cast<std::size_t>(i) >= points.size()) {
        throw std::invalid_argument("a detection's point index is out of range");
      }
    }
    if (d.size() < 3) {
      continue;
    }
    ++s.detected;
    std::unordered_map<int, std::size_t> count;  // points of d on each ground-truth plane
    for (const int i : d) {
      const int plane = plane_of_point[static_cast<std::size_t>(i)];
      if (plane != kNoPlane) {
        ++count[plane];
      }
    }
    const auto top = std::max_element(count.begin(), count.end(), [](const auto& a, const auto& b) {
      return a.second < b.second || (a.second == b.second && a.first > b.first);
    });
    if (top == count.end() ||
        static_cast<double>(top->second) < options.min_share * static_cast<double>(d.size())) {
      continue;
    }
    if (std::abs(fittedNormal(points, d).dot(normalOf(top->first))) >= cos_max) {
      ++s.detected_matched;
      ++matches_of[top->first];
    }
  }
  for (const auto& [plane, idx] : members) {
    if (idx.size() < options.min_gt_points) {
      continue;
    }
    ++s.gt_planes;
    const auto m = matches_of.find(plane);
    s.gt_matched += m != matches_of.end() ? 1 : 0;
    s.gt_split += m != matches_of.end() && m->second > 1 ? 1 : 0;
    if (m == matches_of.end()) {
      s.missed.push_back(plane);
    }
  }
  std::sort(s.missed.begin(), s.missed.end());
  s.precision = s.detected > 0 ? static_cast<double>(s.detected_matched) / s.detected : 0.0;
  s.recall = s.gt_planes > 0 ? static_cast<double>(s.gt_matched) / s.gt_planes : 0.0;
  s.f1 = s.precision + s.recall > 0 ? 2 * s.precision * s.recall / (s.precision + s.recall) : 0.0;
  return s;
}

}  // namespace pmap::eval
