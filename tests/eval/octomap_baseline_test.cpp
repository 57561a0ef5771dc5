// The OctoMap baseline on a synthetic plane scan: occupied voxels on the
// plane, counts and sizes filled in, accuracy of the order of the
// resolution; scans.csv read strictly.
#include "pmap/eval/octomap_baseline.h"

#include <gtest/gtest.h>

#include <octomap/OcTree.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "pmap/common/error.h"
#include "pmap/eval/map_accuracy.h"
#include "surface_test_world.h"

namespace pmap::eval {
namespace {
namespace fs = std::filesystem;
using Eigen::Vector3d;

/// One scan from the origin of a 2 x 2 m wall at y = 2 (1 cm grid).
MapPoints wallScan(int scan = 0) {
  MapPoints p;
  for (int i = 0; i <= 200; ++i) {
    for (int j = 0; j <= 200; ++j) {
      p.xyz.emplace_back(-1.0 + 0.01 * i, 2.0, -1.0 + 0.01 * j);
      p.scan.push_back(scan);
      p.beam.push_back(i * 201 + j);
      p.surface.push_back(-1);
    }
  }
  return p;
}

fs::path writeCsv(const std::string& name, const std::string& text) {
  const fs::path dir = fs::path(PMAP_TEST_TMP_DIR) / "octomap_baseline";
  fs::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

TEST(OctomapBaseline, PlaneScanGivesOccupiedVoxelsOnThePlane) {
  const ScanOrigins origins = {{0, Vector3d::Zero()}};
  for (const double res : {0.05, 0.10}) {
    OctomapOptions o;
    o.resolution_m = res;
    const OctomapResult r = buildOctomap(origins, wallScan(), o);
    EXPECT_EQ(r.scans, 1u);
    EXPECT_EQ(r.points, 201u * 201u);
    EXPECT_GT(r.memory_bytes, 0u);
    EXPECT_GT(r.file_bytes, 0u);
    EXPECT_GE(r.nodes, r.leaves);
    EXPECT_GT(r.occupied_leaves, 0u);
    // About one layer of (2 m / res)^2 voxels, none off the wall's layer.
    const double layer = (2.0 / res + 1) * (2.0 / res + 1);
    EXPECT_GT(r.occupied_centres.size(), 0.9 * (2.0 / res) * (2.0 / res));
    EXPECT_LT(r.occupied_centres.size(), 2.0 * layer);
    for (const Vector3d& c : r.occupied_centres) {
      ASSERT_LE(std::abs(c.y() - 2.0), res) << c.transpose();
    }
  }
}

TEST(OctomapBaseline, AccuracyIsOfTheOrderOfTheResolution) {
  testing::SurfaceTestWorld w;
  w.addRectangle(7, "wall", testing::rectangle({-1, 2, -1}, {2, 0, 0}, {0, 0, 2}));
  const MapPoints scan = wallScan();
  for (std::size_t i = 0; i < scan.xyz.size(); i += 7)
    w.addPoint(scan.xyz[i], 7, -1);
  const auto samples = groundTruthSamples(w.gt, w.points, Rigid2D{}, AccuracyOptions{});
  OctomapOptions o;
  o.resolution_m = 0.1;
  const OctomapResult r = buildOctomap({{0, Vector3d::Zero()}}, scan, o);
  const MapAccuracy a = pointAccuracy(r.occupied_centres, w.gt, samples, Rigid2D{}, {});
  // Samples lie 0.05 m from the voxel centres' layer and up to half a voxel
  // aside: between 0.05 and sqrt(3) * 0.05 m.
  EXPECT_GE(a.gt_to_map.mean_m, 0.05 - 1e-6);
  EXPECT_LE(a.gt_to_map.p95_m, std::sqrt(3.0) * 0.05 + 1e-6);
  EXPECT_NEAR(a.map_to_gt.mean_m, 0.05, 0.02);
}

TEST(OctomapBaseline, BtContentIsWhatWriteBinaryWrites) {
  octomap::OcTree a(0.05), b(0.05);
  octomap::Pointcloud cloud;
  for (const Vector3d& p : wallScan().xyz) {
    cloud.push_back(static_cast<float>(p.x()), static_cast<float>(p.y()),
                    static_cast<float>(p.z()));
  }
  a.insertPointCloud(cloud, octomap::point3d(0, 0, 0));
  b.insertPointCloud(cloud, octomap::point3d(0, 0, 0));
  std::ostringstream written;
  ASSERT_TRUE(a.writeBinary(written));
  EXPECT_EQ(btFileContent(b), written.str());
}

TEST(OctomapBaseline, Item11_ResultKeepsItsBtFileForOctovis) {
  OctomapOptions o;
  o.resolution_m = 0.1;
  const OctomapResult r = buildOctomap({{0, Vector3d::Zero()}}, wallScan(), o);
  EXPECT_EQ(r.file_bytes, r.bt_file.size());
  std::istringstream in(r.bt_file);
  octomap::OcTree back(0.05);
  ASSERT_TRUE(back.readBinary(in));
  EXPECT_DOUBLE_EQ(back.getResolution(), 0.1);
  std::size_t occupied = 0;
  for (auto it = back.begin_leafs(), end = back.end_leafs(); it != end; ++it) {
    if (back.isNodeOccupied(*it)) {
      const auto n = static_cast<std::size_t>(std::lround(it.getSize() / 0.1));
      occupied += n * n * n;
    }
  }
  EXPECT_EQ(occupied, r.occupied_centres.size());
}

TEST(OctomapBaseline, Item11_FileNamesSayTheResolution) {
  EXPECT_EQ(octomapFileName(0.05), "octomap_5cm.bt");
  EXPECT_EQ(octomapFileName(0.10), "octomap_10cm.bt");
  EXPECT_EQ(octomapFileName(0.025), "octomap_2.5cm.bt");
  EXPECT_EQ(octomapFileName(1.0), "octomap_100cm.bt");
}

TEST(OctomapBaseline, PointsWithoutAnOriginAreAnInputError) {
  EXPECT_THROW(buildOctomap({{1, Vector3d::Zero()}}, wallScan(0), OctomapOptions{}), InputError);
  OctomapOptions bad;
  bad.resolution_m = 0;
  EXPECT_THROW(buildOctomap({{0, Vector3d::Zero()}}, wallScan(0), bad), std::invalid_argument);
}

TEST(ScanOrigins, ReadsOriginsByScan) {
  const fs::path csv = writeCsv("scans.csv",
                                "scan,timestamp,label,x,y,z,qw,qx,qy,qz,robot_x,robot_y,robot_yaw,"
                                "points\n3,1.5,LASER_V,1,2,0.3,1,0,0,0,1,2,0,181\n"
                                "5,1.7,LASER_V,1.1,2,0.3,1,0,0,0,1.1,2,0,181\n");
  const ScanOrigins o = readScanOrigins(csv);
  ASSERT_EQ(o.size(), 2u);
  EXPECT_TRUE(o.at(3).isApprox(Vector3d(1, 2, 0.3)));
  EXPECT_TRUE(o.at(5).isApprox(Vector3d(1.1, 2, 0.3)));
}

TEST(ScanOrigins, StrictHeaderNumbersAndDuplicates) {
  EXPECT_THROW(readScanOrigins(writeCsv("h.csv", "id,x\n")), InputError);
  EXPECT_THROW(readScanOrigins(writeCsv("n.csv", "scan,timestamp,label,x,y,z\n1,0,L,a,0,0\n")),
               InputError);
  EXPECT_THROW(readScanOrigins(writeCsv("d.csv",
                                        "scan,timestamp,label,x,y,z\n1,0,L,0,0,0\n"
                                        "1,0,L,0,0,0\n")),
               InputError);
  EXPECT_THROW(readScanOrigins("/nonexistent/scans.csv"), InputError);
}

}  // namespace
}  // namespace pmap::eval
