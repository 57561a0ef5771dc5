// The accuracy figures shared by the planar map, the raw triangle map and
// the OctoMap baseline (doc/evaluation.md, "Baselines"): distances from
// ground-truth surface samples (only where the laser saw them) to the map,
// and from the map back to the ground truth; mean and 95th percentile.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "pmap/eval/ground_truth.h"
#include "pmap/eval/map_files.h"
#include "pmap/eval/pose_metrics.h"
#include "pmap/eval/triangle_index.h"

namespace pmap::eval {

struct AccuracyOptions {
  double sample_spacing_m = 0.05;  ///< ground-truth samples: one per cube of this edge (m)
  double mesh_sample_m = 0.05;     ///< map triangles are sampled at about this spacing (m)
  TriangleIndexOptions index;      ///< distances beyond index.max_distance_m count as it
  bool validate(std::string* why) const;
};

/// Weighted distance statistics (metres); zeros when there are no samples.
struct ErrorStats {
  std::size_t samples = 0;
  double mean_m = 0;
  double p95_m = 0;  ///< smallest d with >= 95 % of the weight at or below it
};

struct MapAccuracy {
  ErrorStats gt_to_map;  ///< ground-truth samples to the nearest map element
  ErrorStats map_to_gt;  ///< map samples to the nearest ground-truth object
};

/// Points with weights (area for mesh samples, 1 for points).
struct WeightedPoints {
  std::vector<Eigen::Vector3d> xyz;
  std::vector<double> weight;
};

ErrorStats errorStats(const std::vector<double>& distances, const std::vector<double>& weights);

/// Ground-truth surface samples where the laser saw them: every mapped point
/// whose beam's true ray hit a ground-truth rectangle (posters count as their
/// wall), moved into the ground-truth frame by `map_to_gt` and replaced by
/// the closest point of that rectangle; then one sample per cube of
/// sample_spacing_m (the first in point order), so dense scans do not weigh
/// more than sparse ones.
std::vector<Eigen::Vector3d> groundTruthSamples(const GroundTruth& gt, const MapPoints& points,
                                                const Rigid2D& map_to_gt,
                                                const AccuracyOptions& options);

/// Samples of a triangle mesh: each triangle cut into n^2 congruent pieces
/// (n = ceil(longest edge / spacing)), one sample at each piece's centroid,
/// weighted by the piece's area.
WeightedPoints meshSamples(const std::vector<Triangle3>& triangles, double spacing_m);

/// The triangles of every ground-truth rectangle (two each).
std::vector<Triangle3> groundTruthTriangles(const GroundTruth& gt);

/// Accuracy of a map given as triangles (world frame of the map; moved by
/// `map_to_gt`). `gt_samples` from groundTruthSamples.
MapAccuracy meshAccuracy(const std::vector<Triangle3>& map_triangles, const GroundTruth& gt,
                         const std::vector<Eigen::Vector3d>& gt_samples, const Rigid2D& map_to_gt,
                         const AccuracyOptions& options);

/// Accuracy of a map given as points (e.g. occupied voxel centres).
MapAccuracy pointAccuracy(const std::vector<Eigen::Vector3d>& map_points, const GroundTruth& gt,
                          const std::vector<Eigen::Vector3d>& gt_samples, const Rigid2D& map_to_gt,
                          const AccuracyOptions& options);

}  // namespace pmap::eval
