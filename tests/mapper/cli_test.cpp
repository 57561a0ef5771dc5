// planar-mapper's command line, exit codes and outputs on small fixtures.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "app_runner.h"
#include "pmap/common/ply.h"
#include "pmap/mapper/planar_mapper_app.h"
#include "rawlog_fixtures.h"

namespace pmap::mapper {
namespace {
namespace fs = std::filesystem;

const fs::path kDefaultIni = fs::path(PMAP_SOURCE_DIR) / "config/default.ini";

int run(const std::vector<std::string>& args) {
  return testing::runMain(&planarMapperMain, "planar-mapper", args);
}

struct Fixture {
  fs::path dir;
  fs::path rawlog;
};

Fixture makeFixture(const std::string& name, int cycles = 20) {
  Fixture f{testing::freshTestDir(name), {}};
  f.rawlog = f.dir / "log.rawlog";
  testing::FixtureOptions o;
  o.cycles = cycles;
  testing::writeFixtureRawlog(f.rawlog, o);
  return f;
}

TEST(MapperCli, WritesEveryOutput) {
  const Fixture f = makeFixture("cli_outputs");
  const fs::path out = f.dir / "out";
  ASSERT_EQ(run({"--rawlog", f.rawlog.string(), "--out", out.string(), "-q"}), 0);
  for (const char* file :
       {"poses.txt", "scans.csv", "points.ply", "raw.wrl", "summary.json", "effective.ini"}) {
    EXPECT_TRUE(fs::exists(out / file)) << file;
  }
  std::ifstream in(out / "summary.json");
  const auto s = nlohmann::json::parse(in);
  // 20 vertical scans at t_k + 0.1 s; the last one lies after the last pose.
  EXPECT_EQ(s["scans"], 19);
  EXPECT_EQ(s["scans_without_pose"], 1);
  EXPECT_EQ(s["points"], 19 * 181);
  EXPECT_EQ(s["raw_triangles"], 18 * 180 * 2);
  EXPECT_GT(s["realtime_factor"].get<double>(), 0.0);
  const PlyVertices v = readPlyVertices(out / "points.ply");
  EXPECT_EQ(v.size(), 19u * 181u);
  EXPECT_EQ(v.names, (std::vector<std::string>{"x", "y", "z", "scan", "beam", "surface"}));
}

TEST(MapperCli, EffectiveIniReproducesTheRun) {
  const Fixture f = makeFixture("cli_effective");
  ASSERT_EQ(run({"--rawlog", f.rawlog.string(), "--out", (f.dir / "a").string(), "-q"}), 0);
  ASSERT_EQ(run({"--config", (f.dir / "a/effective.ini").string(), "--rawlog", f.rawlog.string(),
                 "--out", (f.dir / "b").string(), "-q"}),
            0);
  std::ifstream a(f.dir / "a/poses.txt");
  std::ifstream b(f.dir / "b/poses.txt");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(a), {}),
            std::string(std::istreambuf_iterator<char>(b), {}));
}

TEST(MapperCli, ExitCodes) {
  const Fixture f = makeFixture("cli_exit", 5);
  const std::string log = f.rawlog.string();
  const std::string out = (f.dir / "out").string();
  EXPECT_EQ(run({"--help"}), 0);
  EXPECT_EQ(run({"--no-such-option"}), 1);
  EXPECT_EQ(run({"--config", "/nonexistent.ini", "--rawlog", log, "--out", out}), 1);
  std::ofstream(f.dir / "typo.ini") << "[Sensors]\nstrucure = LASER_V\n[Output]\n";
  EXPECT_EQ(run({"--config", (f.dir / "typo.ini").string(), "--rawlog", log, "--out", out}), 1);
  EXPECT_EQ(run({"--rawlog", (f.dir / "missing.rawlog").string(), "--out", out}), 2);
  EXPECT_EQ(run({"--rawlog", log, "--out", "/proc/pmap-cannot-write", "-q"}), 4);
  EXPECT_EQ(run({"--rawlog", log, "--from-index", "9", "--to-index", "3", "--out", out}), 1);
}

TEST(MapperCli, TruncatedLogIsAnErrorUnlessAccepted) {
  const Fixture f = makeFixture("cli_truncated");
  testing::truncateCopy(f.rawlog, f.dir / "cut.rawlog", 0.63);
  const fs::path out = f.dir / "out";
  EXPECT_EQ(run({"--rawlog", (f.dir / "cut.rawlog").string(), "--out", out.string(), "-q"}), 2);
  EXPECT_FALSE(fs::exists(out / "points.ply"));  // no partial map
  EXPECT_EQ(run({"--rawlog", (f.dir / "cut.rawlog").string(), "--out", out.string(), "-q",
                 "--accept-truncated"}),
            0);
  std::ifstream in(out / "summary.json");
  EXPECT_TRUE(nlohmann::json::parse(in)["input"]["truncated"].get<bool>());
}

TEST(MapperCli, PosesOnlyWritesPosesWithoutAMap) {
  const Fixture f = makeFixture("cli_poses_only");
  const fs::path out = f.dir / "out";
  ASSERT_EQ(run({"--rawlog", f.rawlog.string(), "--out", out.string(), "--poses-only", "-q"}), 0);
  EXPECT_TRUE(fs::exists(out / "poses.txt"));
  EXPECT_FALSE(fs::exists(out / "points.ply"));
}

TEST(MapperCli, GivenPosesReplaceIcp) {
  const Fixture f = makeFixture("cli_given_poses");
  {
    std::ofstream poses(f.dir / "poses.txt");
    for (int k = 0; k <= 10; ++k) {  // every 0.5 s, within max_pose_gap_s
      poses << std::to_string(1767225599.0 + 0.5 * k) << " 5 0 0 0 0 0\n";
    }
  }
  const fs::path out = f.dir / "out";
  ASSERT_EQ(run({"--rawlog", f.rawlog.string(), "--poses", (f.dir / "poses.txt").string(), "--out",
                 out.string(), "-q"}),
            0);
  const PlyVertices v = readPlyVertices(out / "points.ply");
  ASSERT_EQ(v.size(), 20u * 181u);  // every scan lies inside the given trajectory
  for (double x : v.columns[0]) {
    EXPECT_NEAR(x, 5.0, 1e-4);  // the robot stood at x = 5 all the time
  }
}

TEST(MapperCli, PlyCloudInput) {
  const fs::path dir = testing::freshTestDir("cli_cloud");
  std::ofstream(dir / "c.ply") << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                  "property float y\nproperty float z\nend_header\n"
                                  "0 0 0\n1 0 0\nnan 0 0\n";
  const fs::path out = dir / "out";
  ASSERT_EQ(run({"--cloud", (dir / "c.ply").string(), "--out", out.string(), "-q"}), 0);
  std::ifstream in(out / "summary.json");
  const auto s = nlohmann::json::parse(in);
  EXPECT_EQ(s["points"], 2);
  EXPECT_EQ(s["points_dropped_by_reason"]["non_finite"], 1);
}

// An offline EM stopped by its iteration cap says so (a warning in
// summary.json), instead of passing an unfinished model for a whole map.
TEST(MapperCli, AnEmStoppedByItsIterationCapIsAWarning) {
  const fs::path dir = testing::freshTestDir("cli_iteration_cap");
  {
    std::ofstream ply(dir / "c.ply");
    ply << "ply\nformat ascii 1.0\nelement vertex 800\nproperty float x\nproperty float y\n"
           "property float z\nend_header\n";
    for (int i = 0; i < 400; ++i) {  // a floor and a wall, 2 cm apart
      ply << 0.02 * (i % 20) << ' ' << 0.02 * (i / 20) << " 0\n";
      ply << "1 " << 0.02 * (i % 20) << ' ' << 0.02 * (i / 20) + 0.5 << '\n';
    }
    // config/default.ini with max_iterations = 1 (an ini must be whole).
    std::ifstream in(kDefaultIni);
    std::string ini((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ini.replace(ini.find("[PlanarEM]\n"), 11, "[PlanarEM]\nmax_iterations = 1\n");
    ini.replace(ini.find("@include icp.ini"), 16,
                "@include " + (kDefaultIni.parent_path() / "icp.ini").string());
    std::ofstream(dir / "cap.ini") << ini;
  }
  const auto warningsOf = [&](const std::string& name, const std::vector<std::string>& extra) {
    const fs::path out = dir / name;
    std::vector<std::string> args = {"--cloud", (dir / "c.ply").string(), "--out", out.string(),
                                     "-q"};
    args.insert(args.end(), extra.begin(), extra.end());
    EXPECT_EQ(run(args), 0);
    std::ifstream in(out / "summary.json");
    const auto s = nlohmann::json::parse(in);
    std::string all;
    for (const auto& w : s["warnings"]) {
      all += w.get<std::string>() + "\n";
    }
    return std::make_pair(s["termination"].get<std::string>(), all);
  };
  const auto [capped, capped_warnings] =
      warningsOf("capped", {"--config", (dir / "cap.ini").string(), "--mode", "offline"});
  EXPECT_EQ(capped, "max_iterations");
  EXPECT_NE(capped_warnings.find("stopped at [PlanarEM] max_iterations (1)"), std::string::npos)
      << capped_warnings;
  const auto [converged, warnings] =
      warningsOf("converged", {"--config", kDefaultIni.string(), "--mode", "offline"});
  EXPECT_EQ(converged, "converged");
  EXPECT_EQ(warnings.find("max_iterations"), std::string::npos) << warnings;
}

// A cloud of more than 2 x block_points points is mapped in spatial blocks
// (doc/em.md): summary.json says how many, and a block stopped by the
// iteration cap is a warning that says which.
TEST(MapperCli, ALargeCloudIsMappedInSpatialBlocks) {
  const fs::path dir = testing::freshTestDir("cli_blocks");
  {
    std::ofstream ply(dir / "c.ply");
    ply << "ply\nformat ascii 1.0\nelement vertex 28800\nproperty float x\nproperty float y\n"
           "property float z\nend_header\n";
    for (int i = 0; i < 960; ++i) {  // a 48 m corridor's floor and one wall, 5 cm apart
      for (int j = 0; j < 20; ++j) {
        ply << 0.05 * i << ' ' << 0.05 * j << " 0\n";
      }
      for (int j = 0; j < 10; ++j) {
        ply << 0.05 * i << " 1 " << 0.05 * (j + 1) << '\n';
      }
    }
    std::ifstream in(kDefaultIni);
    std::string ini((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ini.replace(ini.find("@include icp.ini"), 16,
                "@include " + (kDefaultIni.parent_path() / "icp.ini").string());
    const auto withBlocks = [&](const std::string& extra) {
      std::string s = ini;
      s.replace(s.find("block_points = 200000"), 21, "block_points = 10000");
      s.replace(s.find("[PlanarEM]\n"), 11, "[PlanarEM]\n" + extra);
      return s;
    };
    std::ofstream(dir / "blocks.ini") << withBlocks("");
    std::ofstream(dir / "cap.ini") << withBlocks("max_iterations = 1\n");
  }
  const auto summaryOf = [&](const std::string& ini) {
    const fs::path out = dir / ("out-" + ini);
    EXPECT_EQ(run({"--cloud", (dir / "c.ply").string(), "--config", (dir / ini).string(),
                   "--no-textures", "--out", out.string(), "-q"}),
              0);
    std::ifstream in(out / "summary.json");
    return nlohmann::json::parse(in);
  };
  const auto s = summaryOf("blocks.ini");
  EXPECT_EQ(s["blocks"], 4);  // 28,800 -> 14,400 -> 7,200
  EXPECT_EQ(s["blocks_unconverged"], 0);
  EXPECT_EQ(s["termination"], "converged");
  EXPECT_GT(s["explained_fraction"].get<double>(), 0.95);
  const auto capped = summaryOf("cap.ini");
  EXPECT_EQ(capped["termination"], "max_iterations");
  EXPECT_EQ(capped["blocks_unconverged"], 4);
  std::string all;
  for (const auto& w : capped["warnings"]) {
    all += w.get<std::string>() + "\n";
  }
  EXPECT_NE(all.find("max_iterations (1) in 4 of its 4 spatial blocks"), std::string::npos) << all;
}

}  // namespace
}  // namespace pmap::mapper
