// Scoring a plane detection against ground-truth planes, the way the plane
// extraction literature scores it (RSPD, Araujo and Oliveira 2020; issue 16's
// peer benchmark): a detected plane matches the ground-truth plane holding at
// least half of its points when their normals are within 30 degrees;
// precision = matched detections / detections, recall = ground-truth planes
// with a matching detection / ground-truth planes, F1 their harmonic mean.
// Ground-truth planes come from the simulator's objects: coplanar rectangles
// are one plane (a wall on both sides of a door), each face of a box is a
// plane, cylinders and rays that hit nothing are no plane.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "pmap/eval/ground_truth.h"

namespace pmap::eval {

/// Label of a point on no ground-truth plane.
constexpr int kNoPlane = -1;

struct GtPlaneOptions {
  double coplanar_deg = 1.0;  ///< rectangles this parallel (degrees) ...
  double coplanar_m = 0.01;   ///< ... and this close (m) are one plane
  bool validate(std::string* why) const;
};

struct GtPlanes {
  std::vector<int> plane_of_point;      ///< per point: plane index, or kNoPlane
  std::vector<Eigen::Vector4d> planes;  ///< (unit normal, offset): n.x = offset
  std::vector<std::string> kinds;       ///< per plane: its first object's kind (box: "KIND face")
};

/// `points` in the ground truth's frame, `labels` their object ids
/// (pointLabels). Points on a box are given the face nearest to them.
GtPlanes groundTruthPlanes(const GroundTruth& gt, const std::vector<Eigen::Vector3d>& points,
                           const std::vector<int>& labels, const GtPlaneOptions& options = {});

struct PlaneScoreOptions {
  double min_share = 0.5;       ///< of a detection's points on its ground-truth plane, (0, 1]
  double max_angle_deg = 30.0;  ///< between the normals, (0, 90]
  std::size_t min_gt_points =
      1;  ///< ground-truth planes with fewer points are not counted in recall
  bool validate(std::string* why) const;
};

struct PlaneScore {
  std::size_t detected = 0;          ///< detections (with >= 3 points)
  std::size_t detected_matched = 0;  ///< ... matching a ground-truth plane
  std::size_t gt_planes = 0;         ///< ground-truth planes with >= min_gt_points points
  std::size_t gt_matched = 0;        ///< ... matched by at least one detection
  std::size_t gt_split = 0;          ///< ... matched by more than one (over-segmented)
  double precision = 0;              ///< detected_matched / detected (0 if none)
  double recall = 0;                 ///< gt_matched / gt_planes (0 if none)
  double f1 = 0;                     ///< 2PR / (P + R), 0 if both are 0
  std::vector<int> missed;           ///< counted ground-truth planes without a match, ascending
};

/// `plane_of_point`: each point's ground-truth plane (kNoPlane: none);
/// `detections`: each detected plane's point indices. Normals are the
/// smallest-eigenvalue directions of each point set's covariance.
/// Throws std::invalid_argument for an index out of range.
PlaneScore scorePlanes(const std::vector<Eigen::Vector3d>& points,
                       const std::vector<int>& plane_of_point,
                       const std::vector<std::vector<int>>& detections,
                       const PlaneScoreOptions& options = {});

/// The unit normal of a point set's least-squares plane (its covariance's
/// smallest eigenvector); zero for fewer than 3 points.
Eigen::Vector3d fittedNormal(const std::vector<Eigen::Vector3d>& points,
                             const std::vector<int>& indices);

}  // namespace pmap::eval
