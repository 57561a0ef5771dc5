// CGAL 5.5 peers of the benchmark (see peer_methods.h). Settings besides
// PeerParams (inlier_m, min_support), all single-threaded:
//
// Both methods: kernel CGAL::Exact_predicates_inexact_constructions_kernel;
//   normals by CGAL::pca_estimate_normals<CGAL::Sequential_tag> over k = 12
//   nearest neighbours (not oriented: both methods compare |cos|). The points
//   are stored as (Point_3, Vector_3, input index) tuples, the index being
//   what the wrappers report.
//
// cgalEfficientRansac: Shape_detection::Efficient_RANSAC with the Plane shape
//   only; Parameters epsilon = inlier_m, min_points = min_support (CGAL raises
//   values below 10 to 10). Left at the defaults of Parameters() in
//   Efficient_RANSAC.h: probability 0.01 (the header's comment says 0.05; the
//   code sets 0.01), normal_threshold 0.9 (cos of about 25 deg),
//   cluster_epsilon 1% of the bounding-box diagonal.
//   Input order: set_input() keeps a reference to the range, and detect()'s
//   preprocessing swaps its elements in place to build the random subsets, so
//   indices_of_assigned_points() index the range *after* detect(); the input
//   index carried in each tuple maps them back to the caller's order.
//   Determinism: Efficient RANSAC draws all its random numbers from
//   CGAL::get_default_random() (a thread-local CGAL::Random seeded from the
//   clock). The wrapper replaces it by CGAL::Random(kRansacSeed) for the call
//   and restores the previous generator afterwards, so every run gives the
//   same planes.
//
// cgalRegionGrowing: Shape_detection::Region_growing (index-based API) with
//   Point_set::K_neighbor_query (k = 12), Point_set::
//   Least_squares_plane_fit_region (distance_threshold = inlier_m,
//   angle_threshold = 25 deg (its default), min_region_size = min_support, at
//   least 1 as CGAL requires) and
//   seeds ordered by Point_set::Least_squares_plane_fit_sorting (best local
//   plane fit first). Regions index the input range, which is not reordered.
//   No randomness.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>
#include <CGAL/Shape_detection/Efficient_RANSAC.h>
#include <CGAL/Shape_detection/Region_growing/Region_growing.h>
#include <CGAL/Shape_detection/Region_growing/Region_growing_on_point_set.h>
#include <CGAL/pca_estimate_normals.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <tuple>
#include <vector>

#include "peer_methods.h"

namespace pmap::peers {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using Vector3 = Kernel::Vector_3;
/// A point, its normal and its index in the caller's input.
using Pwn = std::tuple<Point3, Vector3, int>;
using PwnRange = std::vector<Pwn>;
using PointMap = CGAL::Nth_of_tuple_property_map<0, Pwn>;
using NormalMap = CGAL::Nth_of_tuple_property_map<1, Pwn>;

constexpr unsigned kNormalNeighbours = 12;    // pca_estimate_normals
constexpr std::size_t kQueryNeighbours = 12;  // K_neighbor_query (its default)
constexpr double kAngleThresholdDeg = 25.0;   // Least_squares_plane_fit_region default
constexpr unsigned kRansacSeed = 42;

PwnRange withNormals(const std::vector<Eigen::Vector3d>& points) {
  PwnRange pwns;
  pwns.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d& q = points[i];
    pwns.emplace_back(Point3(q.x(), q.y(), q.z()), Vector3(0, 0, 0), static_cast<int>(i));
  }
  CGAL::pca_estimate_normals<CGAL::Sequential_tag>(
      pwns, kNormalNeighbours, CGAL::parameters::point_map(PointMap()).normal_map(NormalMap()));
  return pwns;
}

/// Replaces CGAL's thread-local default generator for one scope.
class ScopedCgalSeed {
 public:
  explicit ScopedCgalSeed(unsigned seed) : saved_(CGAL::get_default_random()) {
    CGAL::get_default_random() = CGAL::Random(seed);
  }
  ~ScopedCgalSeed() { CGAL::get_default_random() = saved_; }
  ScopedCgalSeed(const ScopedCgalSeed&) = delete;
  ScopedCgalSeed& operator=(const ScopedCgalSeed&) = delete;

 private:
  CGAL::Random saved_;
};

/// The caller's indices of the points at CGAL's `indices` into `pwns`.
std::vector<int> inputIndices(const PwnRange& pwns, const std::vector<std::size_t>& indices) {
  std::vector<int> plane;
  plane.reserve(indices.size());
  for (const std::size_t i : indices)
    plane.push_back(std::get<2>(pwns[i]));
  return plane;
}

}  // namespace

Planes cgalEfficientRansac(const std::vector<Eigen::Vector3d>& points, const PeerParams& p) {
  if (points.size() < 3)
    return {};
  using Traits =
      CGAL::Shape_detection::Efficient_RANSAC_traits<Kernel, PwnRange, PointMap, NormalMap>;
  using Ransac = CGAL::Shape_detection::Efficient_RANSAC<Traits>;
  using Plane = CGAL::Shape_detection::Plane<Traits>;

  PwnRange pwns = withNormals(points);
  const ScopedCgalSeed seed(kRansacSeed);

  Ransac ransac;
  ransac.set_input(pwns);
  ransac.add_shape_factory<Plane>();
  Ransac::Parameters params;  // defaults, see the top of the file
  params.epsilon = p.inlier_m;
  params.min_points = p.min_support;
  ransac.detect(params);

  Planes planes;
  for (const auto& shape : ransac.shapes()) {
    const std::vector<std::size_t>& assigned = shape->indices_of_assigned_points();
    if (assigned.size() < p.min_support)
      continue;  // detect() already enforces it
    planes.push_back(inputIndices(pwns, assigned));
  }
  return planes;
}

Planes cgalRegionGrowing(const std::vector<Eigen::Vector3d>& points, const PeerParams& p) {
  if (points.size() < 3)
    return {};
  using NeighborQuery =
      CGAL::Shape_detection::Point_set::K_neighbor_query<Kernel, PwnRange, PointMap>;
  using RegionType =
      CGAL::Shape_detection::Point_set::Least_squares_plane_fit_region<Kernel, PwnRange, PointMap,
                                                                       NormalMap>;
  using Sorting =
      CGAL::Shape_detection::Point_set::Least_squares_plane_fit_sorting<Kernel, PwnRange,
                                                                        NeighborQuery, PointMap>;
  using RegionGrowing =
      CGAL::Shape_detection::Region_growing<PwnRange, NeighborQuery, RegionType, Sorting::Seed_map>;

  const PwnRange pwns = withNormals(points);
  NeighborQuery neighbors(pwns, kQueryNeighbours, PointMap());
  RegionType region(pwns, p.inlier_m, kAngleThresholdDeg, std::max<std::size_t>(p.min_support, 1),
                    PointMap(), NormalMap());
  Sorting sorting(pwns, neighbors, PointMap());
  sorting.sort();
  RegionGrowing growing(pwns, neighbors, region, sorting.seed_map());

  std::vector<std::vector<std::size_t>> regions;
  growing.detect(std::back_inserter(regions));

  Planes planes;
  planes.reserve(regions.size());
  for (const std::vector<std::size_t>& r : regions)
    planes.push_back(inputIndices(pwns, r));
  return planes;
}

}  // namespace pmap::peers
