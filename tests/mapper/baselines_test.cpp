// map-eval's baseline keys end to end: planar-mapper on the first 200
// structure scans of the simulated default world (true poses), then map-eval
// on its output directory. Sanity of the figures, no timings.
#include <gtest/gtest.h>
#include <unistd.h>

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

class Baselines : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // One directory per process: ctest runs each test of the suite in its
    // own process, in parallel; a shared directory raced (setup failed and
    // gtest reported the tests as skipped).
    out_ = new fs::path(testing::freshTestDir("baselines_" + std::to_string(::getpid())));
    ASSERT_EQ(testing::runMain(&planarMapperMain, "planar-mapper",
                               {"--rawlog", (kSim / "default-obs.rawlog").string(), "--poses",
                                (kSim / "default-obs.poses.txt").string(), "--to-index", "600",
                                "--out", out_->string(), "-q"}),
              0);
    summary_ = new json(json::parse(std::ifstream(*out_ / "summary.json")));
    eval_ = new json(eval::evaluateMap({*out_, kSim / "default-obs.gt.json", {}, true}));
  }
  static void TearDownTestSuite() {
    delete out_;
    delete summary_;
    delete eval_;
  }
  static fs::path* out_;
  static json* summary_;
  static json* eval_;
};
fs::path* Baselines::out_ = nullptr;
json* Baselines::summary_ = nullptr;
json* Baselines::eval_ = nullptr;

TEST_F(Baselines, RawMapGlbHoldsTheRawTriangles) {
  ASSERT_TRUE(eval_->contains("raw_map"));
  const json& raw = (*eval_)["raw_map"];
  EXPECT_EQ(raw["triangles"], (*summary_)["raw_triangles"]);
  EXPECT_EQ(raw["file_bytes"].get<std::uintmax_t>(), fs::file_size(*out_ / "raw.glb"));
  // The raw map is made of the measurements: within a few sigma (2 cm) of the truth.
  EXPECT_LT(raw["mean_error_m"].get<double>(), 0.03);
  EXPECT_LT(raw["map_to_gt_mean_error_m"].get<double>(), 0.03);
}

TEST_F(Baselines, PlanarMapKeys) {
  ASSERT_TRUE(eval_->contains("planar_map"));
  const json& planar = (*eval_)["planar_map"];
  EXPECT_EQ(planar["file"], "map.glb");  // untextured run: map.glb is the geometry
  EXPECT_EQ(planar["triangles"], (*summary_)["map_triangles"]);
  EXPECT_EQ(planar["texture_bytes"], 0);
  EXPECT_LT(planar["mean_error_m"].get<double>(), 0.03);
  EXPECT_LT(planar["p95_error_m"].get<double>(), 0.15);
  EXPECT_LT(planar["map_to_gt_mean_error_m"].get<double>(), 0.03);
  EXPECT_LT(10 * planar["file_bytes"].get<double>(),
            (*eval_)["raw_map"]["file_bytes"].get<double>());
}

TEST_F(Baselines, OctomapAtFiveAndTenCentimetres) {
  ASSERT_TRUE(eval_->contains("octomap"));
  const json& list = (*eval_)["octomap"];
  ASSERT_EQ(list.size(), 2u);
  EXPECT_DOUBLE_EQ(list[0]["resolution_m"].get<double>(), 0.05);
  EXPECT_DOUBLE_EQ(list[1]["resolution_m"].get<double>(), 0.10);
  for (const json& o : list) {
    for (const char* key : {"insert_s", "memory_bytes", "file_bytes", "mean_error_m", "p95_error_m",
                            "nodes", "occupied_leaves"}) {
      ASSERT_TRUE(o.contains(key)) << key;
      EXPECT_GT(o[key].get<double>(), 0.0) << key;
    }
    EXPECT_EQ(o["points"], (*summary_)["points"]);
    EXPECT_EQ(o["scans"], (*summary_)["scans"]);
    // Voxel centres: about a quarter to one voxel from the surfaces.
    const double res = o["resolution_m"].get<double>();
    EXPECT_GT(o["mean_error_m"].get<double>(), 0.2 * res);
    EXPECT_LT(o["mean_error_m"].get<double>(), 1.2 * res);
  }
  EXPECT_LT(list[0]["mean_error_m"].get<double>(), list[1]["mean_error_m"].get<double>());
  EXPECT_GT((*eval_)["baseline_accuracy"]["gt_samples"].get<int>(), 1000);
}

}  // namespace
}  // namespace pmap::mapper
