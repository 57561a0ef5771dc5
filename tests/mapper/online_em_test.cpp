// The online EM on the simulator's default world, against the offline EM on
// the same data (issue: online EM, "must show", non-timing parts).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "app_runner.h"
#include "pmap/eval/map_eval_app.h"
#include "pmap/mapper/planar_mapper_app.h"
#include "rawlog_fixtures.h"

namespace pmap::mapper {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kSim = PMAP_SIM_DIR;

struct Mapped {
  json summary;
  json eval;
};

Mapped mapDefault(const std::string& mode, bool true_poses, const std::string& name) {
  const fs::path out = testing::freshTestDir(name);
  std::vector<std::string> args = {
      "--rawlog", (kSim / "default-obs.rawlog").string(), "--mode", mode, "--out", out.string(),
      "-q"};
  if (true_poses) {
    args.push_back("--poses");
    args.push_back((kSim / "default-obs.poses.txt").string());
  }
  EXPECT_EQ(testing::runMain(&planarMapperMain, "planar-mapper", args), 0);
  std::ifstream in(out / "summary.json");
  return {json::parse(in), eval::evaluateMap({out, kSim / "default-obs.gt.json", {}, true})};
}

void expectCloseToOffline(bool true_poses) {
  const std::string tag = true_poses ? "true" : "icp";
  const Mapped on = mapDefault("online", true_poses, "online_" + tag);
  const Mapped off = mapDefault("offline", true_poses, "offline_" + tag);
  EXPECT_EQ(on.summary["mode"], "online");
  EXPECT_NEAR(on.summary["explained_fraction"].get<double>(),
              off.summary["explained_fraction"].get<double>(), 0.02);
  EXPECT_LE(on.summary["surfaces"].get<int>(), 2 * off.summary["surfaces"].get<int>());
  EXPECT_EQ(on.eval["matched_surfaces"], on.eval["gt_surfaces"]) << on.eval["unmatched"].dump();
  EXPECT_GE(on.summary["compression"].get<double>(), 300.0);
  // One online update per placed structure scan, each timed.
  EXPECT_EQ(on.summary["iterations"], on.summary["scans"]);
  EXPECT_EQ(on.summary["em_per_scan_ms_by_decile"].size(), 10u);
}

TEST(OnlineEm, DefaultWorldTruePosesCloseToOffline) {
  expectCloseToOffline(true);
}

TEST(OnlineEm, DefaultWorldIcpPosesCloseToOffline) {
  expectCloseToOffline(false);
}

TEST(OnlineEm, SnapshotsAreWrittenEveryNScans) {
  const fs::path out = testing::freshTestDir("online_snapshots");
  ASSERT_EQ(testing::runMain(&planarMapperMain, "planar-mapper",
                             {"--rawlog", (kSim / "default-obs.rawlog").string(), "--poses",
                              (kSim / "default-obs.poses.txt").string(), "--to-index", "600",
                              "--snapshot-every", "50", "--out", out.string(), "-q"}),
            0);
  int snapshots = 0;
  for (const auto& e : fs::directory_iterator(out / "snapshots")) {
    snapshots += e.path().extension() == ".wrl" ? 1 : 0;
  }
  // Records 0..600 hold 200 structure scans (3 records per cycle).
  EXPECT_EQ(snapshots, 4);
  EXPECT_TRUE(fs::exists(out / "snapshots/map_000050.wrl"));
}

}  // namespace
}  // namespace pmap::mapper
