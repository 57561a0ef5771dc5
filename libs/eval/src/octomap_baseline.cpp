#include "pmap/eval/octomap_baseline.h"

#include <octomap/OcTree.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "pmap/common/error.h"
#include "pmap/eval/csv_row.h"
#include "pmap/products/output_layout.h"

namespace pmap::eval {
namespace {

constexpr const char* kScansHeaderStart = "scan,timestamp,label,x,y,z";

/// Points grouped by scan, scans in order of first appearance.
std::vector<std::pair<std::int64_t, octomap::Pointcloud>> scanClouds(
    const ScanOrigins& origins, const MapPoints& points, const std::filesystem::path& ply) {
  std::vector<std::pair<std::int64_t, octomap::Pointcloud>> clouds;
  std::unordered_map<std::int64_t, std::size_t> slot;
  for (std::size_t i = 0; i < points.xyz.size(); ++i) {
    const std::int64_t scan = points.scan[i];
    if (origins.count(scan) == 0) {
      throw InputError(ply.string() + ": vertex " + std::to_string(i) + ": scan " +
                       std::to_string(scan) + " has no row in scans.csv");
    }
    const auto [it, fresh] = slot.emplace(scan, clouds.size());
    if (fresh) {
      clouds.emplace_back(scan, octomap::Pointcloud());
    }
    const Eigen::Vector3d& p = points.xyz[i];
    clouds[it->second].second.push_back(static_cast<float>(p.x()), static_cast<float>(p.y()),
                                        static_cast<float>(p.z()));
  }
  return clouds;
}

/// Occupied leaves, pruned ones expanded to voxels of the finest resolution.
std::vector<Eigen::Vector3d> occupiedCentres(const octomap::OcTree& tree, std::size_t& leaves) {
  std::vector<Eigen::Vector3d> centres;
  leaves = 0;
  const double res = tree.getResolution();
  for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
    if (!tree.isNodeOccupied(*it)) {
      continue;
    }
    ++leaves;
    const int n = static_cast<int>(std::lround(it.getSize() / res));
    const octomap::point3d c = it.getCoordinate();
    const Eigen::Vector3d corner(c.x() - 0.5 * it.getSize(), c.y() - 0.5 * it.getSize(),
                                 c.z() - 0.5 * it.getSize());
    for (int x = 0; x < n; ++x) {
      for (int y = 0; y < n; ++y) {
        for (int z = 0; z < n; ++z) {
          centres.push_back(corner + res * Eigen::Vector3d(x + 0.5, y + 0.5, z + 0.5));
        }
      }
    }
  }
  return centres;
}

}  // namespace

std::string btFileContent(octomap::OcTree& tree) {
  // What OcTree::writeBinary writes (maximum likelihood, pruned, then
  // AbstractOccupancyOcTree::writeBinaryConst's header and the data), without
  // the " done." that Debian's liboctomap prints on stderr there.
  tree.toMaxLikelihood();
  tree.prune();
  std::ostringstream s;
  s << "# Octomap OcTree binary file\n# (feel free to add / change comments, but leave the first "
       "line as it is!)\n#\n";
  s << "id " << tree.getTreeType() << "\n";
  s << "size " << tree.size() << "\n";
  s << "res " << tree.getResolution() << "\n";
  s << "data\n";
  tree.writeBinaryData(s);
  return s.str();
}

std::string octomapFileName(double resolution_m) {
  return products::OutputLayout::octomapFile(resolution_m);
}

ScanOrigins readScanOrigins(const std::filesystem::path& csv) {
  requireRegularFile(csv);
  std::ifstream in(csv);
  if (!in) {
    throw InputError(csv.string() + ": cannot open");
  }
  std::string line;
  if (!std::getline(in, line) || line.rfind(kScansHeaderStart, 0) != 0) {
    throw InputError(csv.string() + ":1: header must start with " + kScansHeaderStart);
  }
  ScanOrigins origins;
  for (std::size_t number = 2; std::getline(in, line); ++number) {
    if (line.empty())
      continue;
    const std::vector<std::string> fields = splitCsv(line);
    const RowParser row(fields, csv.string() + ":" + std::to_string(number) + ": ");
    if (fields.size() < 6)
      row.fail("expected at least 6 columns");
    const std::int64_t scan = row.count(0, "scan");
    if (!origins.emplace(scan, Eigen::Vector3d(row.number(3), row.number(4), row.number(5)))
             .second) {
      row.fail("duplicate scan " + std::to_string(scan));
    }
  }
  return origins;
}

bool OctomapOptions::validate(std::string* why) const {
  if (!(resolution_m >= 0.005 && resolution_m <= 10.0)) {
    if (why != nullptr)
      *why = "resolution_m must be in [0.005, 10]";
    return false;
  }
  if (!std::isfinite(max_range_m) || max_range_m == 0.0) {
    if (why != nullptr)
      *why = "max_range_m must be finite and non-zero (< 0: unlimited)";
    return false;
  }
  return true;
}

OctomapResult buildOctomap(const ScanOrigins& origins, const MapPoints& points,
                           const OctomapOptions& options, const std::filesystem::path& points_ply) {
  std::string why;
  if (!options.validate(&why)) {
    throw std::invalid_argument("OctomapOptions: " + why);
  }
  const auto clouds = scanClouds(origins, points, points_ply);
  octomap::OcTree tree(options.resolution_m);
  OctomapResult r;
  r.resolution_m = options.resolution_m;
  const auto t0 = std::chrono::steady_clock::now();
  for (const auto& [scan, cloud] : clouds) {
    const Eigen::Vector3d& o = origins.at(scan);
    tree.insertPointCloud(cloud,
                          octomap::point3d(static_cast<float>(o.x()), static_cast<float>(o.y()),
                                           static_cast<float>(o.z())),
                          options.max_range_m);
    r.points += cloud.size();
  }
  r.insert_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.scans = clouds.size();
  r.memory_bytes = tree.memoryUsage();
  r.nodes = tree.size();
  r.leaves = tree.getNumLeafNodes();
  r.occupied_centres = occupiedCentres(tree, r.occupied_leaves);
  r.bt_file = btFileContent(tree);
  r.file_bytes = r.bt_file.size();
  return r;
}

}  // namespace pmap::eval
