// indoor-sim on voxel worlds (a world file with an "octomap" block): the
// lasers' ranges from known poses in a box room OctoMap wrote, the ground
// truth, determinism and the errors.
#include <gtest/gtest.h>

#include <algorithm>

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <nlohmann/json.hpp>

#include "pmap/common/error.h"
#include "pmap/sim/simulator.h"
#include "sim_test_support.h"
#include "voxel_test_support.h"

namespace pmap::sim {
namespace {

namespace fs = std::filesystem;
using mrpt::obs::CObservation2DRangeScan;

/// A 6 x 4 x 2.5 m box room of 10 cm voxels, free inside [0, 6] x [0, 4] x [0, 2.5].
fs::path roomTree(const fs::path& dir) {
  test::writeBoxRoomTree(dir / "room.bt", 0.1, {0, 0, 0}, {60, 40, 25});
  return dir / "room.bt";
}

SimulatorOptions optionsFor(const fs::path& world, const fs::path& out, std::uint64_t seed = 1) {
  SimulatorOptions o;
  o.world_file = world;
  o.out_prefix = out.string();
  o.seed = seed;
  o.duration_s = 2.0;
  o.progress = false;
  return o;
}

/// The robot drives along y = 1.5 from x = 1 towards +x (yaw 0).
fs::path straightWorld(const fs::path& dir, const std::string& extra = "") {
  roomTree(dir);
  return test::writeText(dir / "box.json",
                         test::voxelWorldJson("room.bt", "[[1.0, 1.5], [5.0, 1.5]]", extra));
}

std::vector<CObservation2DRangeScan::Ptr> scansOf(const fs::path& rawlog) {
  std::vector<CObservation2DRangeScan::Ptr> out;
  for (const auto& obj : test::readRawlog(rawlog)) {
    if (auto s = std::dynamic_pointer_cast<CObservation2DRangeScan>(obj)) {
      out.push_back(s);
    }
  }
  return out;
}

/// (exit code, message) of constructing the simulator; (0, "") if it works.
std::pair<int, std::string> errorOf(const fs::path& world, const fs::path& out) {
  try {
    Simulator s(optionsFor(world, out));
  } catch (const Error& e) {
    return {e.exitCode(), e.what()};
  }
  return {0, ""};
}

// Beams 0, 90 and 180 point right, forward (up for LASER_V) and left; the
// room's faces are at x = 6, y = 0 and 4, z = 2.5; no noise.
TEST(VoxelSimulator, RangesFromKnownPoses) {
  const fs::path dir = test::freshDir("voxel_sim_ranges");
  const SimulationSummary s = Simulator(optionsFor(straightWorld(dir), dir / "run")).run();
  EXPECT_EQ(s.occupied_voxels, 62u * 42u * 27u - 60u * 40u * 25u);
  const auto scans = scansOf(dir / "run.rawlog");
  ASSERT_GE(scans.size(), 4u);
  const auto& h = *scans[0];  // t = 0: robot (1, 1.5), LASER_H at (1.2, 1.5, 0.4)
  ASSERT_EQ(h.sensorLabel, "LASER_H");
  EXPECT_NEAR(h.getScanRange(90), 4.8, 1e-5);
  EXPECT_NEAR(h.getScanRange(0), 1.5, 1e-5);
  EXPECT_NEAR(h.getScanRange(180), 2.5, 1e-5);
  EXPECT_NEAR(h.getScanRange(135), 2.5 * std::sqrt(2.0), 1e-5);
  const auto& v = *scans[1];  // t = 0.1 s: robot (1.04, 1.5), LASER_V at (1.04, 1.5, 0.3)
  ASSERT_EQ(v.sensorLabel, "LASER_V");
  EXPECT_NEAR(v.getScanRange(90), 2.2, 1e-5);
  EXPECT_NEAR(v.getScanRange(0), 1.5, 1e-5);
  EXPECT_NEAR(v.getScanRange(180), 2.5, 1e-5);
  EXPECT_NEAR(v.getScanRange(45), 1.5 * std::sqrt(2.0), 1e-5);  // y = 0 at z = 1.8
  for (const auto& scan : scans) {
    for (std::size_t i = 0; i < scan->getScanSize(); ++i) {
      EXPECT_TRUE(scan->getScanRangeValidity(i));  // a closed room: every beam hits
    }
  }
}

TEST(VoxelSimulator, BeamsWithoutAHitAreMaxRangeReadings) {
  const fs::path dir = test::freshDir("voxel_sim_max_range");
  const fs::path world = straightWorld(dir, R"(, "sensors": {"laser_h": {"max_range_m": 2.0}})");
  Simulator(optionsFor(world, dir / "run")).run();
  const auto h = scansOf(dir / "run.rawlog")[0];
  EXPECT_FALSE(h->getScanRangeValidity(90));  // the wall is 4.8 m away
  EXPECT_FLOAT_EQ(h->getScanRange(90), 2.0f);
  EXPECT_TRUE(h->getScanRangeValidity(0));
}

TEST(VoxelSimulator, GroundTruthNamesTheTree) {
  const fs::path dir = test::freshDir("voxel_sim_gt");
  Simulator(optionsFor(straightWorld(dir), dir / "run")).run();
  const auto gt = nlohmann::json::parse(test::readBytes(dir / "run.gt.json"));
  const auto& o = gt.at("octomap");
  EXPECT_EQ(o.at("file").get<std::string>(), (dir / "room.bt").lexically_normal().string());
  EXPECT_EQ(o.at("file_as_written"), "room.bt");
  EXPECT_EQ(o.at("occupied_voxels"), 62 * 42 * 27 - 60 * 40 * 25);
  EXPECT_DOUBLE_EQ(o.at("resolution_m").get<double>(), 0.1);
  EXPECT_EQ(o.at("bytes"), fs::file_size(dir / "room.bt"));
  EXPECT_TRUE(gt.at("surfaces").empty());
  ASSERT_FALSE(gt.at("structure_scans").empty());
  EXPECT_TRUE(gt.at("structure_scans")[0].at("hits").empty());  // voxels have no ids
  EXPECT_FALSE(gt.at("poses").empty());
  EXPECT_TRUE(gt.at("images").empty());
  EXPECT_TRUE(fs::exists(dir / "run.poses.txt"));
}

TEST(VoxelSimulator, SameSeedSameBytes) {
  const fs::path dir = test::freshDir("voxel_sim_determinism");
  const fs::path world = straightWorld(dir);
  auto run = [&](const std::string& name, std::uint64_t seed) {
    SimulatorOptions o = optionsFor(world, dir / name, seed);
    o.sigma_m = 0.02;
    Simulator(o).run();
    return test::readBytes(dir / (name + ".rawlog")) + test::readBytes(dir / (name + ".gt.json"));
  };
  const std::string a = run("a", 3);
  EXPECT_EQ(a, run("b", 3));
  EXPECT_NE(a, run("c", 4));
}

TEST(VoxelSimulator, TreeErrorsAreInputErrors) {
  const fs::path dir = test::freshDir("voxel_sim_tree_errors");
  const fs::path world =
      test::writeText(dir / "w.json", test::voxelWorldJson("t.bt", "[[1.0, 1.5], [5.0, 1.5]]"));
  auto [code, what] = errorOf(world, dir / "run");
  EXPECT_EQ(code, 2);
  EXPECT_NE(what.find("t.bt: OctoMap tree not found (octomap.file in the world file)"),
            std::string::npos)
      << what;
  test::writeText(dir / "t.bt", "not a tree\n");
  std::tie(code, what) = errorOf(world, dir / "run");
  EXPECT_EQ(code, 2);
  EXPECT_NE(what.find("not an OctoMap binary tree"), std::string::npos) << what;
  octomap::OcTree(0.1).writeBinary((dir / "t.bt").string());  // an empty tree
  std::tie(code, what) = errorOf(world, dir / "run");
  EXPECT_EQ(code, 2);
  EXPECT_NE(what.find("the tree is empty"), std::string::npos) << what;
  EXPECT_FALSE(fs::exists(dir / "run.rawlog"));
}

TEST(VoxelSimulator, WorldFileErrorsAreConfigErrors) {
  const fs::path dir = test::freshDir("voxel_sim_world_errors");
  roomTree(dir);
  const std::string path = "[[1.0, 1.5], [5.0, 1.5]]";
  auto check = [&](const std::string& json, const std::string& expected) {
    const auto [code, what] = errorOf(test::writeText(dir / "w.json", json), dir / "run");
    EXPECT_EQ(code, 1) << what;
    EXPECT_NE(what.find(expected), std::string::npos) << what;
  };
  check(test::voxelWorldJson("room.bt", path, R"(, "sensors": {"cameras": {"enabled": true}})"),
        "sensors.cameras: cameras are not supported in octomap worlds");
  check(test::voxelWorldJson("room.bt", path, R"(, "sensors": {"cameras": {"rate_hz": 1}})"),
        "cameras are not supported");
  check(test::voxelWorldJson("room.bt", path, R"(, "corridors": [])"),
        "corridors: an octomap world takes its geometry from the tree");
  check(R"({"name": "b", "octomap": {"fille": "room.bt"}, "path": {"waypoints": )" + path + "}}",
        "octomap.file: missing required key (found \"fille\": a typo?)");
  check(R"({"name": "b", "octomap": {"file": "room.bt", "max_tree_nodes": 0}, )"
        R"("path": {"waypoints": )" +
            path + "}}",
        "octomap.max_tree_nodes: 0 is out of range");
  check(test::voxelWorldJson("room.bt", "[[1.0, 1.5], [7.0, 1.5]]"),
        "path: the robot (radius 0.25 m) at 0.1 m height touches the occupied voxel (60, ");
  // Cameras explicitly off are fine.
  const auto ok =
      errorOf(test::writeText(dir / "w.json", test::voxelWorldJson("room.bt", path,
                                                                   R"(, "sensors": {"cameras": )"
                                                                   R"({"enabled": false}})")),
              dir / "run");
  EXPECT_EQ(ok.first, 0) << ok.second;
}

// The bundled world through Debian's real building model: the whole path
// passes the clearance check, and the pose laser sees the corridor. (The
// structure laser escapes through gaps in the tree's ceiling: unknown space.)
TEST(VoxelSimulator, Geb079World) {
  const fs::path bt = "/usr/share/doc/liboctomap-dev/examples/data/geb079.bt";
  if (!fs::exists(bt)) {
    GTEST_SKIP() << bt << " not installed (Debian's liboctomap-dev examples): skipped";
  }
  const fs::path dir = test::freshDir("voxel_sim_geb079");
  const SimulatorOptions o =
      optionsFor(fs::path(PMAP_SOURCE_DIR) / "config/worlds/geb079.json", dir / "run");
  const Simulator simulator(o);
  EXPECT_NEAR(simulator.trajectory().length_m(), 32.0, 1e-9);
  EXPECT_EQ(simulator.voxels()->occupiedVoxels(), 185673u);
  Simulator(o).run();
  const auto scans = scansOf(dir / "run.rawlog");
  ASSERT_EQ(scans.size(), 20u);  // 2 s at 5 Hz, two lasers
  for (const auto& scan : scans) {
    int valid = 0;
    float nearest = 1e9f;
    for (std::size_t i = 0; i < scan->getScanSize(); ++i) {
      if (scan->getScanRangeValidity(i)) {
        ++valid;
        nearest = std::min(nearest, scan->getScanRange(i));
      }
    }
    if (scan->sensorLabel == "LASER_H") {
      EXPECT_GT(valid, 170);     // a corridor: nearly every beam hits
      EXPECT_GT(nearest, 0.9f);  // its walls are 1.0 m or more from the laser
    }
  }
}

}  // namespace
}  // namespace pmap::sim
