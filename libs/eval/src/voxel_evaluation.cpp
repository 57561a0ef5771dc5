#include "pmap/eval/voxel_evaluation.h"

#include <octomap/OcTree.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "pmap/common/error.h"
#include "pmap/common/octree_file.h"
#include "pmap/common/quiet_cerr.h"

namespace pmap::eval {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr std::int64_t kHalfRange = std::int64_t{1} << 20;  // voxel indices in [-2^20, 2^20)

std::int64_t cell(double v, double res) {
  return static_cast<std::int64_t>(std::floor(v / res));
}

json statsJson(const ErrorStats& s) {
  return {{"samples", s.samples}, {"mean_m", s.mean_m}, {"p95_m", s.p95_m}};
}

}  // namespace

bool VoxelOptions::validate(std::string* why) const {
  if (!(mesh_sample_m > 0.0) || !std::isfinite(mesh_sample_m) || !(max_distance_m > 0.0) ||
      !std::isfinite(max_distance_m) || max_voxels == 0) {
    *why = "voxel evaluation: mesh_sample_m and max_distance_m must be finite and > 0";
    return false;
  }
  return true;
}

VoxelGroundTruth readVoxelGroundTruth(const fs::path& bt, const VoxelOptions& options) {
  std::error_code ec;
  if (!fs::is_regular_file(bt, ec)) {
    throw InputError(bt.string() + (fs::exists(bt, ec) ? ": not a regular file" : ": not found"));
  }
  // Checked by our own walk of the header and node data first
  // (octree_file.h): OctoMap's reader trusts the file, and a header followed
  // by 1 MB of 0xff bytes crashed map-eval (SIGSEGV) before this. OctoMap then
  // reads the same bytes, from a fresh stream at the first one (the file's
  // stream sought back to 0 gave a slightly different tree on geb079.bt:
  // voxel-to-map mean 4e-11 m apart; not investigated).
  const OctreeLimits limits{options.max_voxels, options.max_voxels};
  const std::string bytes = readOctreeBytes(bt, limits);
  checkOctreeData(bytes, parseOctreeHeader(bytes, bt.string(), limits), bt.string(), limits);
  octomap::OcTree tree(0.1);
  bool read = false;
  {
    std::istringstream in(bytes);
    const QuietCerr quiet;
    read = tree.readBinary(in);
  }
  if (!read) {
    throw InputError(bt.string() + ": damaged OctoMap binary tree (OcTree::readBinary failed)");
  }
  VoxelGroundTruth gt;
  gt.resolution_m = tree.getResolution();
  if (!(gt.resolution_m > 0.0) || !std::isfinite(gt.resolution_m)) {
    throw InputError(bt.string() + ": the tree's resolution is not a positive number");
  }
  const double res = gt.resolution_m;
  for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
    if (!tree.isNodeOccupied(*it)) {
      continue;
    }
    const int n = std::max(1, static_cast<int>(std::lround(it.getSize() / res)));
    const auto count = static_cast<std::size_t>(n) * n * n;
    if (gt.centres.size() + count > options.max_voxels) {
      throw InputError(bt.string() + ": more than " + std::to_string(options.max_voxels) +
                       " occupied voxels");
    }
    const octomap::point3d c = it.getCoordinate();
    const Eigen::Vector3d lo =
        Eigen::Vector3d(c.x(), c.y(), c.z()) - Eigen::Vector3d::Constant(0.5 * (n - 1) * res);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        for (int k = 0; k < n; ++k) {
          gt.centres.push_back(lo + res * Eigen::Vector3d(i, j, k));
        }
      }
    }
  }
  if (gt.centres.empty()) {
    throw InputError(bt.string() + ": no occupied voxel");
  }
  return gt;
}

VoxelDistance::VoxelDistance(const VoxelGroundTruth& gt, double max_distance_m)
    : res_(gt.resolution_m), max_(max_distance_m) {
  keys_.reserve(gt.centres.size());
  for (const Eigen::Vector3d& c : gt.centres) {
    keys_.push_back(key(cell(c.x(), res_), cell(c.y(), res_), cell(c.z(), res_)));
  }
  std::sort(keys_.begin(), keys_.end());
  keys_.erase(std::unique(keys_.begin(), keys_.end()), keys_.end());
}

// Out of range: a key no voxel has (-1; voxel keys are >= 0).
std::int64_t VoxelDistance::key(std::int64_t x, std::int64_t y, std::int64_t z) const {
  if (std::max({std::abs(x), std::abs(y), std::abs(z)}) >= kHalfRange) {
    return -1;
  }
  return ((x + kHalfRange) << 42) | ((y + kHalfRange) << 21) | (z + kHalfRange);
}

// Shell s holds the voxels s cells from p's own (Chebyshev); every voxel of
// shell s + 1 is at least s voxel edges away, so the search stops once the
// best distance is below that.
double VoxelDistance::distance(const Eigen::Vector3d& p) const {
  if (!p.allFinite()) {
    return max_;
  }
  const std::int64_t px = cell(p.x(), res_), py = cell(p.y(), res_), pz = cell(p.z(), res_);
  const auto shells = static_cast<std::int64_t>(std::ceil(max_ / res_)) + 1;
  double best = max_;
  for (std::int64_t s = 0; s <= shells; ++s) {
    for (std::int64_t dx = -s; dx <= s; ++dx) {
      for (std::int64_t dy = -s; dy <= s; ++dy) {
        const bool face = std::abs(dx) == s || std::abs(dy) == s;
        for (std::int64_t dz = -s; dz <= s; dz += face ? 1 : std::max<std::int64_t>(1, 2 * s)) {
          const std::int64_t k = key(px + dx, py + dy, pz + dz);
          if (k < 0 || !std::binary_search(keys_.begin(), keys_.end(), k)) {
            continue;
          }
          const Eigen::Vector3d centre =
              res_ * (Eigen::Vector3d(px + dx, py + dy, pz + dz).array() + 0.5).matrix();
          const Eigen::Vector3d gap =
              ((p - centre).cwiseAbs().array() - 0.5 * res_).max(0.0).matrix();
          best = std::min(best, gap.norm());
        }
      }
    }
    if (best <= static_cast<double>(s) * res_) {
      break;
    }
  }
  return best;
}

VoxelAccuracy voxelAccuracy(const VoxelGroundTruth& gt, const std::vector<Triangle3>& map_triangles,
                            const VoxelOptions& options) {
  std::string why;
  if (!options.validate(&why)) {
    throw std::invalid_argument(why);
  }
  VoxelAccuracy a;
  a.voxels = gt.centres.size();
  const WeightedPoints samples = meshSamples(map_triangles, options.mesh_sample_m);
  const VoxelDistance to_voxels(gt, options.max_distance_m);
  std::vector<double> d;
  d.reserve(samples.xyz.size());
  for (const Eigen::Vector3d& p : samples.xyz) {
    d.push_back(to_voxels.distance(p));
  }
  a.map_to_voxels = errorStats(d, samples.weight);

  TriangleIndexOptions index;
  index.max_distance_m = options.max_distance_m;
  const TriangleIndex to_map(map_triangles, index);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (const Triangle3& t : map_triangles) {
    for (const Eigen::Vector3d* v : {&t.a, &t.b, &t.c}) {
      lo = lo.cwiseMin(*v);
      hi = hi.cwiseMax(*v);
    }
  }
  lo.array() -= gt.resolution_m;
  hi.array() += gt.resolution_m;
  d.clear();
  std::size_t covered = 0, covered_in_box = 0;
  for (const Eigen::Vector3d& c : gt.centres) {
    d.push_back(to_map.distance(c));
    const bool near = d.back() <= gt.resolution_m;
    covered += near ? 1 : 0;
    if ((c.array() >= lo.array()).all() && (c.array() <= hi.array()).all()) {
      ++a.voxels_in_map_box;
      covered_in_box += near ? 1 : 0;
    }
  }
  a.voxels_to_map = errorStats(d, std::vector<double>(d.size(), 1.0));
  a.coverage = static_cast<double>(covered) / static_cast<double>(a.voxels);
  a.coverage_in_map_box = a.voxels_in_map_box > 0 ? static_cast<double>(covered_in_box) /
                                                        static_cast<double>(a.voxels_in_map_box)
                                                  : 0.0;
  return a;
}

json voxelJson(const VoxelAccuracy& a, const VoxelGroundTruth& gt, const fs::path& bt,
               const VoxelOptions& options) {
  return {{"file", bt.string()},
          {"resolution_m", gt.resolution_m},
          {"occupied_voxels", a.voxels},
          {"mesh_sample_m", options.mesh_sample_m},
          {"max_distance_m", options.max_distance_m},
          {"map_to_voxels", statsJson(a.map_to_voxels)},
          {"voxels_to_map", statsJson(a.voxels_to_map)},
          {"coverage", a.coverage},
          {"voxels_in_map_box", a.voxels_in_map_box},
          {"coverage_in_map_box", a.coverage_in_map_box}};
}

}  // namespace pmap::eval
