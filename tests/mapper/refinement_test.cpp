// Fusion and Ceres refinement on the simulator's default world, scored by
// map-eval against the ground truth (issue: Ceres refinement, "must show").
#include <gtest/gtest.h>

#include <fstream>
#include <map>
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

struct MappedRun {
  json summary;
  json eval;
};

MappedRun mapDefaultWorld(const std::string& name, const std::vector<std::string>& extra) {
  const fs::path out = testing::freshTestDir(name);
  std::vector<std::string> args = {"--rawlog", (kSim / "default-obs.rawlog").string(),
                                   "--poses",  (kSim / "default-obs.poses.txt").string(),
                                   "--out",    out.string(),
                                   "-q"};
  args.insert(args.end(), extra.begin(), extra.end());
  EXPECT_EQ(testing::runMain(&planarMapperMain, "planar-mapper", args), 0);
  std::ifstream in(out / "summary.json");
  return {json::parse(in), eval::evaluateMap({out, kSim / "default-obs.gt.json", {}, true})};
}

std::map<int, double> normalErrors(const json& eval) {
  std::map<int, double> out;
  for (const json& p : eval["per_surface"]) {
    out[p["gt_id"].get<int>()] = p["normal_error_deg"].get<double>();
  }
  return out;
}

TEST(Refinement, OfflineTruePosesClosesTheSeamsWithoutTurningPlanes) {
  const MappedRun em = mapDefaultWorld("refine_off_em", {"--mode", "offline", "--no-refine"});
  const MappedRun refined = mapDefaultWorld("refine_off", {"--mode", "offline"});
  EXPECT_FALSE(em.summary.contains("refinement"));
  const json& r = refined.summary["refinement"];
  EXPECT_TRUE(r["ran"].get<bool>());
  EXPECT_EQ(r["termination"], "CONVERGENCE");
  EXPECT_GE(r["seams"].size(), 10u);
  EXPECT_TRUE(r["reverted_ids"].empty());
  EXPECT_LT(r["final_cost"].get<double>(), r["initial_cost"].get<double>());
  // The world's 8 recessed doors end on their walls' openings.
  EXPECT_EQ(r["openings"].size(), 8u);

  const json& a = em.eval;
  const json& b = refined.eval;
  ASSERT_EQ(b["matched_surfaces"], b["gt_surfaces"]);
  EXPECT_GE(b["seam_sides"].get<int>(), 10);
  EXPECT_LE(b["seam_gap_m"]["mean"].get<double>(), 0.01);
  EXPECT_LT(b["seam_gap_m"]["mean"].get<double>(), a["seam_gap_m"]["mean"].get<double>());
  EXPECT_LE(b["corner_error_closed_m"]["mean"].get<double>(), 0.02);
  EXPECT_LE(b["surfaces"].get<double>(), 1.2 * b["gt_surfaces"].get<double>());
  const auto before = normalErrors(a);
  for (const auto& [gt_id, after] : normalErrors(b)) {
    EXPECT_LE(after, before.at(gt_id) + 0.1) << "ground-truth surface " << gt_id;
  }
}

TEST(Refinement, OnlineModeIsRefinedToo) {
  const MappedRun refined = mapDefaultWorld("refine_on", {});
  EXPECT_EQ(refined.summary["mode"], "online");
  EXPECT_TRUE(refined.summary["refinement"]["ran"].get<bool>());
  EXPECT_GE(refined.summary["timing_s"]["refine"].get<double>(), 0.0);
  EXPECT_EQ(refined.eval["matched_surfaces"], refined.eval["gt_surfaces"]);
  EXPECT_LE(refined.eval["seam_gap_m"]["mean"].get<double>(), 0.01);
  EXPECT_LE(refined.eval["corner_error_closed_m"]["mean"].get<double>(), 0.02);
}

}  // namespace
}  // namespace pmap::mapper
