// planar-mapper on the simulator's default world (written by the CTest
// fixture default_world, see CMakeLists.txt), scored with map-eval's code
// against the simulator's own ground truth.
#include <gtest/gtest.h>
#include <mrpt/graphs/CNetworkOfPoses.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app_runner.h"
#include "pmap/common/ply.h"
#include "pmap/eval/ground_truth.h"
#include "pmap/eval/map_eval_app.h"
#include "pmap/eval/pose_metrics.h"
#include "pmap/mapper/planar_mapper_app.h"
#include "pmap/poses/pose_graph.h"
#include "pmap/poses/poses_file.h"
#include "rawlog_fixtures.h"
#include "test_files.h"

namespace pmap::mapper {
namespace {
namespace fs = std::filesystem;

const fs::path kSim = PMAP_SIM_DIR;

int run(const std::vector<std::string>& args) {
  return testing::runMain(&planarMapperMain, "planar-mapper", args);
}

fs::path mapWorld(const std::string& name, const std::string& prefix, bool true_poses) {
  const fs::path out = testing::freshTestDir(name);
  std::vector<std::string> args = {"--rawlog", (kSim / (prefix + ".rawlog")).string(), "--out",
                                   out.string(), "-q"};
  if (true_poses) {
    args.push_back("--poses");
    args.push_back((kSim / (prefix + ".poses.txt")).string());
  }
  EXPECT_EQ(run(args), 0);
  return out;
}

nlohmann::json evaluate(const fs::path& map, const std::string& prefix) {
  return eval::evaluateMap({map, kSim / (prefix + ".gt.json"), map / "eval.json", true});
}

std::string fileBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Independent geometry check: the simulator finds hits by its own ray casting;
// the mapper projects the recorded ranges with MRPT's conventions.
TEST(DefaultWorld, WithTruePosesPointsLieOnTheirLabelledSurfaces) {
  const fs::path map = mapWorld("world_true", "default-obs", true);
  const auto e = evaluate(map, "default-obs");
  const auto& c = e["label_check"];
  EXPECT_GE(c["fraction_within_3sigma"].get<double>(), 0.99);
  EXPECT_GT(c["labelled"].get<int>(), 80000);
  EXPECT_EQ(c["unlabelled"], 0);
  EXPECT_LT(e["pose_ate_m"].get<double>(), 1e-6);
}

// One beam by hand: the vertical laser's middle beam points straight up from
// its mount at 0.3 m, so under the flat 2.7 m ceiling it measures 2.4 m and its
// point sits at the robot's x, y.
TEST(DefaultWorld, StraightUpBeamHitsTheCeilingAtHeightMinusMount) {
  const fs::path map = mapWorld("world_up_beam", "default-obs", true);
  const eval::GroundTruth gt = eval::readGroundTruth(kSim / "default-obs.gt.json");
  const PlyVertices v = readPlyVertices(map / "points.ply");
  const double sigma = gt.sigma_m;
  int ceiling_hits = 0;
  int within = 0;
  for (size_t i = 0; i < v.size(); ++i) {
    if (v.columns[4][i] != 90) {
      continue;
    }
    const int id = gt.hits.at(static_cast<int>(v.columns[3][i]))[90];
    const eval::GtRectangle* s = gt.surface(id);
    ASSERT_NE(s, nullptr);
    if (s->kind != "ceiling") {
      continue;
    }
    ++ceiling_hits;
    const double range = v.columns[2][i] - 0.3;
    within += std::abs(range - 2.4) <= 3 * sigma ? 1 : 0;
  }
  EXPECT_GT(ceiling_hits, 500);
  EXPECT_GE(within, 0.99 * ceiling_hits);
}

TEST(DefaultWorld, EstimatedPosesAreWithinFiveCentimetres) {
  const fs::path map = mapWorld("world_icp", "default-obs", false);
  const auto e = evaluate(map, "default-obs");
  EXPECT_LE(e["pose_ate_m"].get<double>(), 0.05);
  std::printf("pose_ate_m %.4f, first-pose aligned %.4f, points within 3 sigma %.4f\n",
              e["pose_ate_m"].get<double>(), e["pose"]["ate_first_pose_aligned_m"].get<double>(),
              e["label_check"]["fraction_within_3sigma"].get<double>());
}

TEST(DefaultWorld, BothRawlogFormatsGiveIdenticalPoints) {
  const fs::path obs = mapWorld("world_fmt_obs", "default-obs", true);
  const fs::path sf = mapWorld("world_fmt_sf", "default-sf", true);
  EXPECT_EQ(fileBytes(obs / "points.ply"), fileBytes(sf / "points.ply"));
  EXPECT_EQ(fileBytes(obs / "scans.csv"), fileBytes(sf / "scans.csv"));
}

TEST(DefaultWorld, BothRawlogFormatsGiveTheSameIcpPoses) {
  const fs::path obs = mapWorld("world_fmt_icp_obs", "default-obs", false);
  const fs::path sf = mapWorld("world_fmt_icp_sf", "default-sf", false);
  const PlyVertices a = readPlyVertices(obs / "points.ply");
  const PlyVertices b = readPlyVertices(sf / "points.ply");
  ASSERT_EQ(a.size(), b.size());
  double worst = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      worst = std::max(worst, std::abs(a.columns[k][i] - b.columns[k][i]));
    }
    ASSERT_EQ(a.columns[3][i], b.columns[3][i]);
    ASSERT_EQ(a.columns[4][i], b.columns[4][i]);
  }
  std::printf("largest coordinate difference obs vs sf with ICP poses: %.3g m\n", worst);
  EXPECT_LT(worst, 1e-3);
}

/// Rows of a CSV file with a header line, split at commas.
std::vector<std::vector<std::string>> csvRows(const fs::path& p) {
  std::ifstream in(p);
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<std::string>> rows;
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::stringstream ss(line);
    for (std::string f; std::getline(ss, f, ',');) {
      fields.push_back(f);
    }
    rows.push_back(fields);
  }
  return rows;
}

// Issue 15 items 4 and 6: driven there and back with loop closure on (as
// config/default.ini has it), the closures rewrite the past trajectory; every structure scan of the
// map ends at the final trajectory's pose of its time (the online map was repaired, not left at the
// poses it was first placed with), and poses.graph holds the graph MRPT reads.
TEST(DefaultReturnWorld, Item15_WithLoopClosureTheMapFollowsTheFinalPoses) {
  const fs::path out = testing::freshTestDir("world_return_loops");
  ASSERT_EQ(run({"--rawlog", (kSim / "default-return.rawlog").string(), "--out", out.string(),
                 "--no-textures", "-q"}),
            0);
  std::ifstream summary_file(out / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(summary_file);
  const nlohmann::json& loops = summary["poses"]["loop_closure"];
  std::printf("loop closure: %s\n", loops.dump().c_str());
  ASSERT_GT(loops["trajectory_rewrites"].get<int>(), 0);
  EXPECT_GT(loops["structure_scans_moved"].get<int>(), 0);
  EXPECT_GT(loops["online_repairs"]["points_moved"].get<int>(), 0);

  const poses::Trajectory final_poses = poses::readPosesFile(out / "poses.txt");
  const auto scans =
      csvRows(out / "scans.csv");  // scan,timestamp,...,robot_x,robot_y,robot_yaw,points
  ASSERT_GT(scans.size(), 1000u);
  double worst = 0;
  for (const auto& row : scans) {
    const auto pose = final_poses.at(std::stod(row[1]), 1.0);
    ASSERT_TRUE(pose.has_value()) << row[0];
    worst = std::max(
        {worst, std::abs(pose->x - std::stod(row[10])), std::abs(pose->y - std::stod(row[11]))});
  }
  // ScanPlacer::follow leaves a scan whose pose changed by <= 0.1 mm; 1 um printing
  std::printf("worst scan offset from the final poses: %.2e m\n", worst);
  EXPECT_LT(worst, 1.01e-4) << "a scan stayed where the drifting trajectory had put it";

  mrpt::graphs::CNetworkOfPoses2DInf graph;
  graph.loadFromTextFile((out / "poses.graph").string());
  EXPECT_EQ(graph.nodes.size(), loops["keyframes"].get<std::size_t>());
  // odometry edges between consecutive keyframes, the accepted loops and the path constraints
  EXPECT_EQ(graph.edges.size(), graph.nodes.size() - 1 + loops["accepted"].get<std::size_t>() +
                                    loops["path_constraints"].get<std::size_t>());
}

// planar-mapper --poses-only on a simulated world with config/default.ini
// (loop closure on) or default.ini with loop closure off; its pose errors
// against the world's true poses and summary.json's loop_closure block (null
// when off).
struct LoopRun {
  eval::PoseErrors errors;
  nlohmann::json loops;
};

LoopRun runPoses(const std::string& world, const std::string& name, const fs::path& ini) {
  const fs::path out = testing::freshTestDir(name);
  LoopRun r;
  EXPECT_EQ(run({"--config", ini.string(), "--rawlog", (kSim / (world + ".rawlog")).string(),
                 "--out", out.string(), "--poses-only", "-q"}),
            0);
  r.errors = eval::comparePoses(poses::readPosesFile(out / "poses.txt"),
                                poses::readPosesFile(kSim / (world + ".poses.txt")));
  std::ifstream summary_file(out / "summary.json");
  r.loops = nlohmann::json::parse(summary_file)["poses"]["loop_closure"];
  std::printf("%s: ATE %.3f m, max %.3f m\n", name.c_str(), r.errors.ate_m, r.errors.max_error_m);
  return r;
}

LoopRun runLoopClosure(const std::string& world, bool closing) {
  const std::string name = "world_" + world + (closing ? "_on" : "_off");
  const fs::path ini =
      closing ? fs::path(PMAP_SOURCE_DIR) / "config/default.ini"
              : testing::editedDefaultIni(testing::freshTestDir(name + "_ini"),
                                          "loop_closure = true", "loop_closure = false");
  return runPoses(world, name, ini);
}

// A loop closure farther than this from the truth joins two different
// places. Why 0.5 m: the search treats poses within ambiguity_distance_m
// (1 m) of its best as one answer, so along a corridor an accepted loop is
// the right place registered to within that; the false loops these worlds
// produced before the ambiguity checks were 0.6-8.9 m wrong. Measured on
// the loop world (2026-12-03, 187 loops): median 0.03 m, p90 0.07 m, worst
// 0.30 m (along the corridor at one corner: an accuracy defect that the
// trajectory's ATE bound and doc/pose-accuracy.md report, not a false loop).
constexpr double kFalseLoopM = 0.5;

// The largest distance between an accepted loop closure's match (the newer
// keyframe in the older one's frame) and the same relative pose of the true
// trajectory.
double worstLoopError(const nlohmann::json& loops, const std::string& world) {
  const poses::Trajectory truth = poses::readPosesFile(kSim / (world + ".poses.txt"));
  double worst = 0;
  for (const nlohmann::json& c : loops["closures"]) {
    const auto a = truth.at(c["older_t"].get<double>(), 1.0);
    const auto b = truth.at(c["newer_t"].get<double>(), 1.0);
    EXPECT_TRUE(a && b);
    if (!a || !b) {
      continue;
    }
    const poses::Pose2 t = poses::between({a->x, a->y, a->yaw}, {b->x, b->y, b->yaw});
    const double e = std::hypot(t.x - c["x_m"].get<double>(), t.y - c["y_m"].get<double>());
    if (e > 0.5 * kFalseLoopM) {
      std::printf("loop %.1f s -> %.1f s is %.2f m from the truth\n", c["older_t"].get<double>(),
                  c["newer_t"].get<double>(), e);
    }
    worst = std::max(worst, e);
  }
  return worst;
}

// Issue 15: the loop world, a ring corridor around a 60 x 40 m block driven
// twice (402 m). Its corridors alias along their axis (straight walls match
// at any shift, the doors are 8 m apart): before the ambiguity and
// window-edge checks, loop closure accepted a loop 8.6 m wrong when the
// first lap closed and the pose ATE went from 0.32 m to 2.5 m. With loop
// closure the trajectory must be better than without, every keyframe of the
// optimised graph near its true pose, every accepted loop near the truth.
TEST(LoopWorld, Item15_LoopClosureImprovesTheRingWithoutFalseLoops) {
  const LoopRun off = runLoopClosure("loop", false);
  const LoopRun on = runLoopClosure("loop", true);
  EXPECT_GT(on.loops["accepted"].get<int>(), 20);              // both laps' revisits close
  EXPECT_GT(on.loops["rejected_as_ambiguous"].get<int>(), 0);  // the corridors do alias
  // Without loop closure the ICP front end drifts (0.32 m ATE, 0.7 m at
  // worst); a single false loop bends the ring by metres.
  EXPECT_LT(on.errors.ate_m, off.errors.ate_m);
  EXPECT_LT(on.errors.max_error_m, 0.5);
  EXPECT_LT(worstLoopError(on.loops, "loop"), kFalseLoopM);
}

// Issue 15: the aliasing world (config/worlds/aliasing.json), two identical
// corridors 6 m apart, the second one entered after 140 m without a
// revisit, when the search window has grown to 8 m: the first corridor's
// keyframes are candidates and match the second's scans (measured: 2 such
// matches scored 0.86, unique in their window, free space agreeing;
// the graph refused them, Cauchy loss and chi2). No accepted loop may be a
// false one, and loop closure must still help.
TEST(AliasingWorld, Item15_IdenticalCorridorsGiveNoFalseLoop) {
  const LoopRun off = runLoopClosure("aliasing", false);
  const LoopRun on = runLoopClosure("aliasing", true);
  EXPECT_GT(on.loops["accepted"].get<int>(), 0);
  EXPECT_LT(worstLoopError(on.loops, "aliasing"), kFalseLoopM);
  EXPECT_LT(on.errors.ate_m, off.errors.ate_m);
}

// Issue 15: on a loop-free world the pose graph's keyframe edges, refined
// point-to-line against the recent keyframes (scan_refiner.h), take out
// what MRPT's ICP leaves of the odometry's drift (measured: about a tenth
// of its 1 deg/m heading drift, 0.1 deg/m; ATE 0.17 m on this U-shaped
// corridor, 0.025 m with the refined edges, 0.021 m with the scans between
// keyframes refined too; issue 15's target is 0.03 m).
TEST(OfficeWorld, Item15_RefinedKeyframeEdgesRemoveTheFrontEndsDrift) {
  const fs::path ini = testing::editedDefaultIni(
      testing::freshTestDir("office_unrefined_ini"), "loop_closure = true",
      "loop_closure = true\nkeyframe_refinement = false");
  const LoopRun unrefined = runPoses("office", "office_unrefined", ini);
  const LoopRun refined =
      runPoses("office", "office_refined", fs::path(PMAP_SOURCE_DIR) / "config/default.ini");
  // nearly every keyframe edge: a walled corridor always has lines to match
  EXPECT_GE(refined.loops["refined_edges"].get<double>(),
            0.95 * refined.loops["keyframes"].get<double>());
  // about five scans between two keyframes (0.08 m apart, keyframes every 0.5 m)
  EXPECT_GT(refined.loops["refined_scans"].get<double>(),
            3.0 * refined.loops["keyframes"].get<double>());
  EXPECT_EQ(unrefined.loops["refined_edges"].get<std::size_t>(), 0u);
  EXPECT_EQ(unrefined.loops["refined_scans"].get<std::size_t>(), 0u);
  EXPECT_LT(refined.errors.ate_m, 0.5 * unrefined.errors.ate_m);
  EXPECT_LT(refined.errors.ate_m, 0.03);
}

}  // namespace
}  // namespace pmap::mapper
