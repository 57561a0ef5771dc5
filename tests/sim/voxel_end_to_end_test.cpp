// The built programs on a small voxel world: indoor-sim drives the robot
// through a box room OctoMap wrote, planar-mapper maps it (true poses) and
// map-eval scores the map against the room's occupied voxels and the poses
// against the run's gt.json.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "process_runner.h"
#include "sim_test_support.h"
#include "voxel_test_support.h"

namespace pmap::sim {
namespace {

namespace fs = std::filesystem;
using testing::programPath;
using testing::runProcess;

TEST(VoxelEndToEnd, BoxRoomMapScoredAgainstItsVoxels) {
  const fs::path dir = test::freshDir("voxel_end_to_end");
  // 10 x 3 x 2.5 m inside, 10 cm voxels, a 0.8 m cube against the right wall.
  test::writeBoxRoomTree(dir / "room.bt", 0.1, {0, 0, 0}, {100, 30, 25}, {48, 0, 0}, 8);
  test::writeText(dir / "room.json",
                  R"({"name": "room", "octomap": {"file": "room.bt"},
                      "path": {"waypoints": [[1.0, 1.6], [9.0, 1.6]]}})");
  const auto sim = runProcess({programPath("indoor-sim"), "--world", (dir / "room.json").string(),
                               "--seed", "2", "--quiet", "--out", (dir / "run").string()});
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  const auto mapper = runProcess(
      {programPath("planar-mapper"), "--rawlog", (dir / "run.rawlog").string(), "--poses",
       (dir / "run.poses.txt").string(), "--out", (dir / "map").string(), "-q"});
  ASSERT_EQ(mapper.exit_code, 0) << mapper.err;
  const auto eval =
      runProcess({programPath("map-eval"), "--map", (dir / "map").string(), "--gt",
                  (dir / "run.gt.json").string(), "--gt-octomap", (dir / "room.bt").string(),
                  "--out", (dir / "map" / "eval.json").string(), "-q"});
  ASSERT_EQ(eval.exit_code, 0) << eval.err;
  std::ifstream in(dir / "map" / "eval.json");
  const auto doc = nlohmann::json::parse(in);
  EXPECT_LT(doc.at("pose_ate_m").get<double>(), 1e-6);
  const auto& v = doc.at("voxel_gt");
  // Measured: mean 0.2 mm, p95 0.7 mm, 94 % of the voxels in the map's box covered.
  EXPECT_LT(v.at("map_to_voxels").at("mean_m").get<double>(), 0.02) << v.dump();
  EXPECT_LT(v.at("map_to_voxels").at("p95_m").get<double>(), 0.05) << v.dump();
  EXPECT_GT(v.at("coverage_in_map_box").get<double>(), 0.8) << v.dump();
  std::ifstream summary_in(dir / "map" / "summary.json");
  const auto summary = nlohmann::json::parse(summary_in);
  EXPECT_GT(summary.at("explained_fraction").get<double>(), 0.95);
}

TEST(VoxelEndToEnd, AMissingTreeExitsTwoWithOneLine) {
  const fs::path dir = test::freshDir("voxel_end_to_end_missing");
  test::writeText(dir / "w.json", R"({"name": "w", "octomap": {"file": "missing.bt"},
                                      "path": {"waypoints": [[1.0, 1.6], [9.0, 1.6]]}})");
  const auto sim = runProcess({programPath("indoor-sim"), "--world", (dir / "w.json").string(),
                               "--quiet", "--out", (dir / "run").string()});
  EXPECT_EQ(sim.exit_code, 2);
  EXPECT_EQ(sim.err, "indoor-sim: error: " + (dir / "missing.bt").string() +
                         ": OctoMap tree not found (octomap.file in the world file)\n");
  EXPECT_FALSE(fs::exists(dir / "run.rawlog"));
}

}  // namespace
}  // namespace pmap::sim
