#pragma once
// Library plane-detection methods the benchmark compares against (its "peers"):
// PCL's RANSAC and region growing, CGAL's Efficient RANSAC and region growing.
// Each wrapper runs single-threaded and deterministically (fixed seeds); the
// settings beyond PeerParams are listed at the top of pcl_methods.cpp and
// cgal_methods.cpp.

#include <Eigen/Core>
#include <cstddef>
#include <vector>

namespace pmap::peers {

/// The benchmark's one parameter rule (issue 16): every method gets these; any
/// other setting is the library's documented default unless stated in the .cpp.
struct PeerParams {
  double inlier_m = 0.05;         ///< inlier distance (m): 2.5 sigma
  std::size_t min_support = 200;  ///< fewest points per plane
};

/// Detected planes, each a list of indices into the input points (disjoint).
using Planes = std::vector<std::vector<int>>;

/// PCL SACSegmentation (RANSAC, plane model), extracting planes one at a time.
Planes pclSacSegmentation(const std::vector<Eigen::Vector3d>& points, const PeerParams& p);
/// PCL RegionGrowing on k-nearest-neighbour normals; each cluster is a plane.
Planes pclRegionGrowing(const std::vector<Eigen::Vector3d>& points, const PeerParams& p);
/// CGAL Shape_detection::Efficient_RANSAC with plane shapes only.
Planes cgalEfficientRansac(const std::vector<Eigen::Vector3d>& points, const PeerParams& p);
/// CGAL Shape_detection::Region_growing with least-squares plane regions.
Planes cgalRegionGrowing(const std::vector<Eigen::Vector3d>& points, const PeerParams& p);

}  // namespace pmap::peers
