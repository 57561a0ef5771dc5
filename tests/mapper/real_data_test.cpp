// planar-mapper on MRPT's real datasets (Debian package mrpt-common).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app_runner.h"
#include "pmap/mapper/planar_mapper_app.h"
#include "pmap/poses/poses_file.h"
#include "rawlog_fixtures.h"

namespace pmap::mapper {
namespace {
namespace fs = std::filesystem;

const fs::path kDatasets = "/usr/share/mrpt/datasets";
const fs::path kSena = kDatasets / "2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog";
const fs::path kConfigDir = fs::path(PMAP_SOURCE_DIR) / "config";

int run(const std::vector<std::string>& args) {
  return testing::runMain(&planarMapperMain, "planar-mapper", args);
}

nlohmann::json summary(const fs::path& out) {
  std::ifstream in(out / "summary.json");
  return nlohmann::json::parse(in);
}

// Reference: MRPT's own icp-slam 2.5.8 on the same log with the MRPT sections
// of config/mrpt-sena.ini, final line of log_estimated_path.txt ("223 4.230092
// -18.432017 -1.533012"); regenerate with scripts/icp-slam-reference.sh.
constexpr double kIcpSlamX = 4.230092;
constexpr double kIcpSlamY = -18.432017;
constexpr double kIcpSlamYaw = -1.533012;

poses::TimedPose finalPose(const std::vector<std::string>& extra, const std::string& name) {
  const fs::path out = testing::freshTestDir(name);
  std::vector<std::string> args = {"--config",     (kConfigDir / "mrpt-sena.ini").string(),
                                   "--rawlog",     kSena.string(),
                                   "--poses-only", "--quiet",
                                   "--out",        out.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  EXPECT_EQ(run(args), 0);
  return poses::readPosesFile(out / "poses.txt").poses().back();
}

TEST(SenaLog, SameObservationsAsIcpSlamGiveItsFinalPose) {
  const poses::TimedPose p = finalPose({"--skip-leading-frame"}, "sena_skip");
  EXPECT_NEAR(p.pose.x, kIcpSlamX, 0.01);
  EXPECT_NEAR(p.pose.y, kIcpSlamY, 0.01);
  EXPECT_NEAR(p.pose.yaw, kIcpSlamYaw, 0.5 * M_PI / 180);
}

TEST(SenaLog, KeepingTheLeadingFrameUsesAllFrames) {
  const fs::path out = testing::freshTestDir("sena_keep");
  ASSERT_EQ(run({"--config", (kConfigDir / "mrpt-sena.ini").string(), "--rawlog", kSena.string(),
                 "--poses-only", "--quiet", "--out", out.string()}),
            0);
  const auto s = summary(out);
  EXPECT_EQ(s["input"]["pose_scans"], 225);  // MRPT's pair reader gives 224
  EXPECT_EQ(s["poses"]["count"], 225);
  const poses::TimedPose p = poses::readPosesFile(out / "poses.txt").poses().back();
  // Measured gap to icp-slam (which never sees the first frame): 2.6 cm, 0.09 deg.
  EXPECT_LT(std::hypot(p.pose.x - kIcpSlamX, p.pose.y - kIcpSlamY), 0.1);
}

TEST(SenaLog, WithoutAStructureSensorMappingIsAnInputError) {
  const fs::path out = testing::freshTestDir("sena_nostructure");
  EXPECT_EQ(run({"--config", (kConfigDir / "mrpt-sena.ini").string(), "--rawlog", kSena.string(),
                 "--quiet", "--out", out.string()}),
            2);
  EXPECT_FALSE(fs::exists(out / "summary.json"));
}

TEST(RgbdFrame, MapsAsStructurePointsWithTheIdentityPose) {
  const fs::path out = testing::freshTestDir("rgbd");
  ASSERT_EQ(run({"--config", (kConfigDir / "mrpt-rgbd.ini").string(), "--rawlog",
                 (kDatasets / "tests_rgbd.rawlog").string(), "--mode", "raw", "--quiet", "--out",
                 out.string()}),
            0);
  const auto s = summary(out);
  EXPECT_EQ(s["poses"]["source"], "identity");
  EXPECT_EQ(s["scans"], 1);
  EXPECT_EQ(s["measurements"], 640 * 480);
  // 273,225 of the 307,200 pixels carry a depth; the rest have none.
  EXPECT_EQ(s["points"], 273225);
  EXPECT_EQ(s["points_dropped_by_reason"]["invalid"], 640 * 480 - 273225);
  EXPECT_GT(s["raw_triangles"].get<int>(), 400000);
}

struct SurfaceRow {
  Eigen::Vector3d normal;
  double offset = 0;
  int support = 0;
};

std::vector<SurfaceRow> surfaces(const fs::path& out) {
  std::ifstream in(out / "surfaces.csv");
  std::string line;
  std::getline(in, line);
  std::vector<SurfaceRow> rows;
  while (std::getline(in, line)) {
    double v[18];
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream row(line);
    for (double& x : v) {
      row >> x;
    }
    rows.push_back({Eigen::Vector3d(v[1], v[2], v[3]), v[4], static_cast<int>(v[17])});
  }
  return rows;
}

// The Kinect frame shows a wall behind a bookshelf. In the default mode (no
// --mode) the range image goes to the offline EM (it has no scan-line order
// for the online EM), coarse to fine (config/mrpt-rgbd.ini). The wall is one
// surface although its depth comes in disparity steps of 1-2 cm and bends by
// +-3 cm towards the image corners (two interleaved planes would explain it
// better: they occupy the same place and are fused); the bookshelf's front
// faces, about 35 cm in front of it, are other surfaces.
TEST(RgbdFrame, DefaultModeMapsTheWallAsOneSurfaceAndTheShelfApart) {
  const fs::path out = testing::freshTestDir("rgbd_em");
  ASSERT_EQ(run({"--config", (kConfigDir / "mrpt-rgbd.ini").string(), "--rawlog",
                 (kDatasets / "tests_rgbd.rawlog").string(), "--quiet", "--out", out.string()}),
            0);
  const auto s = summary(out);
  EXPECT_EQ(s["mode"], "offline");
  EXPECT_NE(s["mode_note"].get<std::string>().find("range image"), std::string::npos);
  EXPECT_GE(s["explained_fraction"].get<double>(), 0.95);
  EXPECT_NE(s["em_message"].get<std::string>().find("on a sample of 20000 points"),
            std::string::npos);
  const std::vector<SurfaceRow> rows = surfaces(out);
  EXPECT_GE(rows.size(), 3u);
  const auto wall = std::max_element(
      rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.support < b.support; });
  ASSERT_NE(wall, rows.end());
  EXPECT_GT(std::abs(wall->normal.x()), std::cos(20 * M_PI / 180));  // faces the camera
  EXPECT_GT(std::abs(wall->offset), 2.05);                           // ~2.15 m away
  int copies = 0;      // other surfaces at the wall's place
  double shelf = 1e9;  // the nearest large camera-facing surface
  for (const SurfaceRow& r : rows) {
    const double cos_angle = std::abs(r.normal.dot(wall->normal));
    const double depth = std::abs(r.offset);
    if (&r != &*wall && cos_angle > std::cos(10 * M_PI / 180) &&
        std::abs(depth - std::abs(wall->offset)) < 0.1) {
      ++copies;
    }
    if (std::abs(r.normal.x()) > std::cos(20 * M_PI / 180) && r.support > 1000) {
      shelf = std::min(shelf, depth);
    }
  }
  EXPECT_EQ(copies, 0);
  EXPECT_LT(shelf, 1.9);  // the bookshelf's front, ~1.8 m away
}

// The VLP-16 sweep (outdoors: road, trees, a building) with its own config:
// a range image of 16 rings by azimuth steps (neighbours across rings too),
// mapped with at least three surfaces, the ground (horizontal) among them,
// and the building's wall.
TEST(VelodyneSweep, MapsAsARingGridWithGroundAndWall) {
  const fs::path out = testing::freshTestDir("velodyne");
  ASSERT_EQ(
      run({"--config", (kConfigDir / "mrpt-velodyne.ini").string(), "--rawlog",
           (kDatasets / "test_velodyne_VLP16.rawlog").string(), "--quiet", "--out", out.string()}),
      0);
  const auto s = summary(out);
  EXPECT_EQ(s["poses"]["source"], "identity");
  EXPECT_EQ(s["points"], 11305);
  // 16 rings x the sweep's azimuth steps; cells without a return are invalid.
  EXPECT_EQ(s["measurements"].get<int>() % 16, 0);
  EXPECT_EQ(s["points"].get<int>() + s["points_dropped_by_reason"]["invalid"].get<int>(),
            s["measurements"].get<int>());
  EXPECT_GT(s["raw_triangles"].get<int>(), 1000);  // quads across rings
  const std::vector<SurfaceRow> rows = surfaces(out);
  EXPECT_GE(rows.size(), 3u);
  int ground = 0;
  int walls = 0;
  for (const SurfaceRow& r : rows) {
    ground += std::abs(r.normal.z()) > std::cos(10 * M_PI / 180) && r.support >= 200 ? 1 : 0;
    walls += std::abs(r.normal.z()) < std::sin(10 * M_PI / 180) && r.support >= 200 ? 1 : 0;
  }
  EXPECT_GE(ground, 1);
  EXPECT_GE(walls, 1);
}

}  // namespace
}  // namespace pmap::mapper
