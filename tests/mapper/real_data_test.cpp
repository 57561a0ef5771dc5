// planar-mapper on MRPT's real datasets (Debian package mrpt-common).
#include <gtest/gtest.h>

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

// The Kinect frame shows a wall behind a bookshelf: the offline EM must give
// the wall and the bookshelf's front faces as different surfaces (both face
// the camera, +x, about 35 cm apart in depth).
TEST(RgbdFrame, WallAndBookshelfFacesAreSeparateSurfaces) {
  const fs::path out = testing::freshTestDir("rgbd_em");
  ASSERT_EQ(run({"--config", (kConfigDir / "mrpt-rgbd.ini").string(), "--rawlog",
                 (kDatasets / "tests_rgbd.rawlog").string(), "--mode", "offline", "--quiet",
                 "--out", out.string()}),
            0);
  std::ifstream in(out / "surfaces.csv");
  std::string line;
  std::getline(in, line);
  double wall_offset = 0;
  double shelf_offset = 1e9;
  int surfaces = 0;
  while (std::getline(in, line)) {
    double v[18];
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream row(line);
    for (double& x : v) {
      row >> x;
    }
    ++surfaces;
    const bool facing_camera = std::abs(v[1]) > std::cos(20 * M_PI / 180);  // |n . x|
    if (facing_camera && v[17] > 1000) {
      const double depth = std::abs(v[4]);
      wall_offset = std::max(wall_offset, depth);
      shelf_offset = std::min(shelf_offset, depth);
    }
  }
  EXPECT_GE(surfaces, 3);
  EXPECT_GT(wall_offset, 2.05);  // the wall, ~2.15 m away
  EXPECT_LT(shelf_offset, 1.9);  // the bookshelf's front, ~1.8 m away
}

TEST(VelodyneSweep, MapsAsAnUnorganisedCloud) {
  const fs::path out = testing::freshTestDir("velodyne");
  ASSERT_EQ(
      run({"--config", (kConfigDir / "mrpt-rgbd.ini").string(), "--rawlog",
           (kDatasets / "test_velodyne_VLP16.rawlog").string(), "--quiet", "--out", out.string()}),
      0);
  const auto s = summary(out);
  EXPECT_EQ(s["poses"]["source"], "identity");
  EXPECT_GT(s["points"].get<int>(), 10000);
  EXPECT_EQ(s["raw_triangles"], 0);
}

}  // namespace
}  // namespace pmap::mapper
