#include "pmap/sim/indoor_sim_app.h"

#include <gtest/gtest.h>

#include "pmap/common/error.h"
#include "sim_test_support.h"

namespace pmap::sim {
namespace {

std::string configErrorOf(const std::vector<std::string>& args) {
  try {
    IndoorSimApp app;
    app.initialize(args);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(IndoorSimApp, ParsesTheCommandLine) {
  IndoorSimApp app;
  ASSERT_TRUE(app.initialize({"indoor-sim", "--out", "x/run", "--seed", "12", "--sigma", "0.05",
                              "--format", "sf", "--duration", "2.5", "--no-cameras", "--quiet"}));
  EXPECT_EQ(app.options().seed, 12u);
  EXPECT_EQ(app.options().sigma_m, 0.05);
  EXPECT_EQ(app.options().format, RawlogFormat::kSensoryFrames);
  EXPECT_EQ(app.options().duration_s, 2.5);
  EXPECT_FALSE(app.options().cameras);
  EXPECT_FALSE(app.options().progress);
  // Without --world: the bundled default world of the source tree.
  EXPECT_EQ(app.options().world_file,
            std::filesystem::path(PMAP_SOURCE_DIR) / "config/worlds/default.json");
}

TEST(IndoorSimApp, HelpPrintsAndStops) {
  IndoorSimApp app;
  testing::internal::CaptureStdout();
  EXPECT_FALSE(app.initialize({"indoor-sim", "--help"}));
  EXPECT_NE(testing::internal::GetCapturedStdout().find("--out"), std::string::npos);
}

TEST(IndoorSimApp, UsageErrorsAreOneLineConfigErrors) {
  EXPECT_NE(configErrorOf({"indoor-sim"}).find("required: --out <PREFIX>"), std::string::npos);
  EXPECT_NE(configErrorOf({"indoor-sim", "--out", "x", "--seed", "-3"}).find("--seed"),
            std::string::npos);
  EXPECT_NE(configErrorOf({"indoor-sim", "--out", "x", "--sigma", "2cm"}).find("--sigma"),
            std::string::npos);
  EXPECT_NE(configErrorOf({"indoor-sim", "--out", "x", "--format", "raw"}), "");
  EXPECT_NE(configErrorOf({"indoor-sim", "--out", "x", "--bogus"}), "");
  EXPECT_NE(configErrorOf({"indoor-sim", "--out", "x", "--duration", "0"}), "");
  for (const auto& e : {configErrorOf({"indoor-sim"}), configErrorOf({"indoor-sim", "--out"})}) {
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  }
}

TEST(IndoorSimApp, ErrorsCarryTheirExitCodes) {
  const auto dir = test::freshDir("app_errors");
  IndoorSimApp missing_world;
  ASSERT_TRUE(missing_world.initialize(
      {"indoor-sim", "--world", (dir / "none.json").string(), "--out", (dir / "r").string()}));
  try {
    missing_world.run();
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.exitCode(), 1);
  }
  const std::string world = test::writeText(dir / "tiny.json", test::tinyWorldJson()).string();
  IndoorSimApp unwritable;
  ASSERT_TRUE(unwritable.initialize(
      {"indoor-sim", "--world", world, "--out", "/proc/pmap-no-such-dir/r", "--quiet"}));
  try {
    unwritable.run();
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.exitCode(), 4);
  }
}

TEST(IndoorSimApp, RunsAShortSimulation) {
  const auto dir = test::freshDir("app_run");
  const std::string world = test::writeText(dir / "tiny.json", test::tinyWorldJson()).string();
  IndoorSimApp app;
  ASSERT_TRUE(app.initialize({"indoor-sim", "--world", world, "--out", (dir / "r").string(),
                              "--duration", "1", "--quiet"}));
  const SimulationSummary s = app.run();
  EXPECT_EQ(s.cycles, 5u);
  for (const char* f : {"r.rawlog", "r.gt.json", "r.poses.txt", "r_Images"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
  }
}

}  // namespace
}  // namespace pmap::sim
