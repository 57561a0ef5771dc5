// PCL 1.13 peers of the benchmark (see peer_methods.h). Settings besides
// PeerParams (inlier_m, min_support), all single-threaded:
//
// pclSacSegmentation: pcl::SACSegmentation<PointXYZ>, SACMODEL_PLANE,
//   SAC_RANSAC, setOptimizeCoefficients(true), setDistanceThreshold(inlier_m),
//   setMaxIterations(1000) (as PCL's planar segmentation tutorial).
//   Left at PCL's defaults: probability 0.99, setNumberOfThreads(-1) (= no
//   OpenMP), no radius-limited sampling. Planes are extracted one at a time:
//   fit, keep the inliers as a plane if there are >= min_support, remove them
//   and fit again on the rest; stop at the first fit with < min_support inliers
//   or when < min_support points remain.
//   Determinism: SACSegmentation is built with random = false (the default),
//   and segment() creates a new model and a new RANSAC object on each call,
//   both seeding their boost::mt19937 with 12345u: every run gives the same
//   planes.
//
// pclRegionGrowing: normals by pcl::NormalEstimation<PointXYZ, Normal>
//   (not the OMP variant) over the k = 30 nearest neighbours (KdTree search);
//   pcl::RegionGrowing<PointXYZ, Normal> with setMinClusterSize(min_support),
//   setNumberOfNeighbours(30) and the same KdTree. Left at PCL's defaults (from
//   the RegionGrowing constructor, region_growing.hpp): max cluster size
//   unlimited, smooth mode on, smoothness threshold 30 deg (between the
//   normals of a point and its neighbour), curvature test on with threshold
//   0.05 (points above it join a region but do not grow it), residual test off
//   (its threshold, 0.05, is unused). Each cluster is a plane. No randomness.
//   NormalEstimation's normals point to the viewpoint (0,0,0); RegionGrowing
//   compares |cos|, so the orientation does not matter.
//
// Both: PCL's console verbosity is lowered to L_ALWAYS for the duration of a
//   call (and restored after it), so that degenerate inputs do not flood
//   stderr with PCL warnings ("Sample points too similar or collinear!").

#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/console/print.h>
#include <pcl/features/normal_3d.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/region_growing.h>
#include <pcl/segmentation/sac_segmentation.h>

#include <algorithm>
#include <vector>

#include "peer_methods.h"

namespace pmap::peers {
namespace {

constexpr int kSacMaxIterations = 1000;  // PCL planar segmentation tutorial
constexpr int kNormalNeighbours = 30;    // normals and region growing

/// Silences PCL's console output for one scope (the level is process-wide).
class ScopedPclQuiet {
 public:
  ScopedPclQuiet() : saved_(pcl::console::getVerbosityLevel()) {
    pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
  }
  ~ScopedPclQuiet() { pcl::console::setVerbosityLevel(saved_); }
  ScopedPclQuiet(const ScopedPclQuiet&) = delete;
  ScopedPclQuiet& operator=(const ScopedPclQuiet&) = delete;

 private:
  pcl::console::VERBOSITY_LEVEL saved_;
};

pcl::PointCloud<pcl::PointXYZ>::Ptr toCloud(const std::vector<Eigen::Vector3d>& points,
                                            const std::vector<int>& which) {
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  cloud->reserve(which.size());
  for (const int i : which) {
    const Eigen::Vector3d& q = points[static_cast<std::size_t>(i)];
    cloud->push_back(pcl::PointXYZ(static_cast<float>(q.x()), static_cast<float>(q.y()),
                                   static_cast<float>(q.z())));
  }
  return cloud;
}

std::vector<int> allIndices(std::size_t n) {
  std::vector<int> all(n);
  for (std::size_t i = 0; i < n; ++i)
    all[i] = static_cast<int>(i);
  return all;
}

}  // namespace

Planes pclSacSegmentation(const std::vector<Eigen::Vector3d>& points, const PeerParams& p) {
  if (points.size() < 3)
    return {};
  const std::size_t min_points = std::max<std::size_t>(p.min_support, 3);
  const ScopedPclQuiet quiet;

  pcl::SACSegmentation<pcl::PointXYZ> seg(/*random=*/false);
  seg.setModelType(pcl::SACMODEL_PLANE);
  seg.setMethodType(pcl::SAC_RANSAC);
  seg.setOptimizeCoefficients(true);
  seg.setDistanceThreshold(p.inlier_m);
  seg.setMaxIterations(kSacMaxIterations);
  seg.setNumberOfThreads(-1);  // PCL's default: sequential RANSAC

  Planes planes;
  std::vector<int> remaining = allIndices(points.size());  // cloud index -> input index
  while (remaining.size() >= min_points) {
    seg.setInputCloud(toCloud(points, remaining));
    pcl::PointIndices inliers;
    pcl::ModelCoefficients coefficients;
    seg.segment(inliers, coefficients);
    if (inliers.indices.size() < min_points)
      break;

    std::vector<int> plane;
    plane.reserve(inliers.indices.size());
    std::vector<char> taken(remaining.size(), 0);
    for (const auto i : inliers.indices) {
      const auto k = static_cast<std::size_t>(i);
      if (taken[k])
        continue;  // PCL's inlier lists hold no duplicates; be safe
      taken[k] = 1;
      plane.push_back(remaining[k]);
    }
    std::vector<int> rest;
    rest.reserve(remaining.size() - plane.size());
    for (std::size_t k = 0; k < remaining.size(); ++k)
      if (!taken[k])
        rest.push_back(remaining[k]);
    remaining.swap(rest);
    planes.push_back(std::move(plane));
  }
  return planes;
}

Planes pclRegionGrowing(const std::vector<Eigen::Vector3d>& points, const PeerParams& p) {
  if (points.size() < 3)
    return {};
  const ScopedPclQuiet quiet;
  const pcl::PointCloud<pcl::PointXYZ>::Ptr cloud = toCloud(points, allIndices(points.size()));
  const pcl::search::Search<pcl::PointXYZ>::Ptr tree(new pcl::search::KdTree<pcl::PointXYZ>);

  pcl::PointCloud<pcl::Normal>::Ptr normals(new pcl::PointCloud<pcl::Normal>);
  pcl::NormalEstimation<pcl::PointXYZ, pcl::Normal> estimator;
  estimator.setInputCloud(cloud);
  estimator.setSearchMethod(tree);
  estimator.setKSearch(kNormalNeighbours);
  estimator.compute(*normals);

  pcl::RegionGrowing<pcl::PointXYZ, pcl::Normal> growing;
  growing.setInputCloud(cloud);
  growing.setInputNormals(normals);
  growing.setSearchMethod(tree);
  growing.setNumberOfNeighbours(kNormalNeighbours);
  growing.setMinClusterSize(static_cast<pcl::uindex_t>(p.min_support));

  std::vector<pcl::PointIndices> clusters;
  growing.extract(clusters);

  Planes planes;
  planes.reserve(clusters.size());
  for (const pcl::PointIndices& c : clusters) {
    if (c.indices.size() < p.min_support)
      continue;  // extract() already drops these
    planes.emplace_back(c.indices.begin(), c.indices.end());
  }
  return planes;
}

}  // namespace pmap::peers
