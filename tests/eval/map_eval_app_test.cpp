// map-eval end to end on files: a synthetic gt.json and a map directory
// (poses.txt, points.ply, surfaces.csv) written by the test.
#include "pmap/eval/map_eval_app.h"

#include <gtest/gtest.h>

#include "nan_glb.h"

#include <octomap/OcTree.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>

#include "pmap/common/error.h"
#include "pmap/common/ply.h"
#include "pmap/products/map_gltf.h"
#include "pmap/products/output_manifest.h"
#include "surface_test_world.h"

namespace pmap::eval {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;
using testing::rectangle;
using testing::SurfaceTestWorld;

json vec(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

void writeGroundTruth(const SurfaceTestWorld& w, const fs::path& path) {
  json doc = {{"format", "pmap-gt/1"}, {"world", "test"}, {"sigma_m", 0.01}};
  doc["poses"] = {{0.0, 0, 0, 0, 0, 0, 0}, {10.0, 5, 0, 0, 0, 0, 0}};
  doc["surfaces"] = json::array();
  for (const auto& s : w.gt.surfaces) {
    doc["surfaces"].push_back(
        {{"id", s.id},
         {"kind", s.kind},
         {"corners", {vec(s.corners[0]), vec(s.corners[1]), vec(s.corners[2]), vec(s.corners[3])}},
         {"normal", vec(s.normal)},
         {"holes", json::array()},
         {"parent", nullptr}});
  }
  doc["clutter"] = json::array();
  for (const auto& c : w.gt.cylinders) {
    doc["clutter"].push_back({{"id", c.id},
                              {"kind", c.kind},
                              {"shape", "cylinder"},
                              {"centre", {c.centre.x(), c.centre.y()}},
                              {"radius_m", c.radius},
                              {"z_min_m", c.z_min},
                              {"z_max_m", c.z_max}});
  }
  doc["structure_scans"] = json::array();
  for (const auto& [index, hits] : w.gt.hits) {
    doc["structure_scans"].push_back({{"index", index}, {"timestamp", 1.0}, {"hits", hits}});
  }
  std::ofstream(path) << doc.dump();
}

void writePointsPly(const MapPoints& p, const fs::path& path) {
  std::vector<std::vector<double>> cols(6);
  for (std::size_t i = 0; i < p.xyz.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      cols[k].push_back(p.xyz[i][k]);
    }
    cols[3].push_back(p.scan[i]);
    cols[4].push_back(p.beam[i]);
    cols[5].push_back(p.surface[i]);
  }
  writePlyVertices(path, {{"x", "double", &cols[0]},
                          {"y", "double", &cols[1]},
                          {"z", "double", &cols[2]},
                          {"scan", "int", &cols[3]},
                          {"beam", "int", &cols[4]},
                          {"surface", "int", &cols[5]}});
}

void writeSurfacesCsv(const std::vector<MapSurface>& surfaces, const fs::path& path) {
  std::ofstream out(path);
  out << kSurfacesCsvHeader << "\n";
  out.precision(17);
  for (const auto& s : surfaces) {
    out << s.id << "," << s.normal.x() << "," << s.normal.y() << "," << s.normal.z() << ","
        << s.offset_m;
    for (const auto& c : s.corners) {
      out << "," << c.x() << "," << c.y() << "," << c.z();
    }
    out << "," << s.support << "\n";
  }
}

/// A wall and a floor seen by 300 beams each (map surfaces 0, 1), a small
/// panel (not eligible) and a bin whose 40 points are rejected.
SurfaceTestWorld world() {
  SurfaceTestWorld w;
  w.addRectangle(0, "wall", rectangle({0, 0, 0}, {10, 0, 0}, {0, 0, 3}));
  w.addRectangle(1, "floor", rectangle({0, 0, 0}, {0, 2, 0}, {10, 0, 0}));
  w.addRectangle(2, "panel", rectangle({0, 2, 0}, {1, 0, 0}, {0, 0, 1}));
  w.addCylinder(3, {5, 1}, 0.2);
  w.addGrid(0, 0, 20, 15);
  w.addGrid(1, 1, 20, 15);
  w.addGrid(2, -1, 5, 5);
  for (int i = 0; i < 40; ++i) {
    w.addPoint({5, 1.2, 0.02 * i}, 3, -1);
  }
  w.surfaces = {w.perfectSurface(0, 0), w.perfectSurface(1, 1)};
  return w;
}

/// Writes the world's gt.json and map directory; returns the arguments.
MapEvalArgs writeWorld(const SurfaceTestWorld& w, const std::string& name, bool with_csv = true) {
  const fs::path dir = fs::path(PMAP_TEST_TMP_DIR) / "map_eval_app" / name;
  fs::remove_all(dir);
  fs::create_directories(dir / "map");
  writeGroundTruth(w, dir / "run.gt.json");
  std::ofstream(dir / "map" / "poses.txt")
      << "# timestamp x y z yaw pitch roll\n0.0 0 0 0 0 0 0\n10.0 5 0 0 0 0 0\n";
  writePointsPly(w.points, dir / "map" / "points.ply");
  // Every point is in scan 0 (SurfaceTestWorld), seen from (5, 1, 1).
  std::ofstream(dir / "map" / "scans.csv") << "scan,timestamp,label,x,y,z\n0,1.0,LASER_V,5,1,1\n";
  if (with_csv) {
    writeSurfacesCsv(w.surfaces, dir / "map" / "surfaces.csv");
  }
  return {dir / "map", dir / "run.gt.json", dir / "eval.json", true};
}

TEST(MapEvalApp, PerfectMapFromFiles) {
  const json doc = evaluateMap(writeWorld(world(), "perfect"));
  EXPECT_LT(doc["pose_ate_m"].get<double>(), 1e-9);
  EXPECT_TRUE(doc.contains("label_check"));
  EXPECT_EQ(doc["surfaces"], 2);
  EXPECT_EQ(doc["gt_surfaces"], 2);
  EXPECT_EQ(doc["matched_surfaces"], 2);
  EXPECT_TRUE(doc["unmatched"].empty());
  EXPECT_NEAR(doc["corner_error_m"]["max"].get<double>(), 0.0, 1e-9);
  EXPECT_NEAR(doc["offset_error_m"]["max"].get<double>(), 0.0, 1e-9);
  EXPECT_NEAR(doc["normal_error_deg"]["max"].get<double>(), 0.0, 1e-6);
  EXPECT_EQ(doc["label_recall"], 1.0);
  EXPECT_EQ(doc["label_precision"], 1.0);
  EXPECT_EQ(doc["clutter_points"], 40);
  EXPECT_EQ(doc["clutter_rejected_fraction"], 1.0);
  EXPECT_EQ(doc["matched_by_kind"]["floor"]["matched"], 1);
  EXPECT_EQ(doc["per_surface"].size(), 2u);
}

TEST(MapEvalApp, WithoutSurfacesCsvOnlyTheEarlierKeys) {
  const json doc = evaluateMap(writeWorld(world(), "no_csv", false));
  EXPECT_TRUE(doc.contains("label_check"));
  EXPECT_FALSE(doc.contains("matched_surfaces"));
  EXPECT_FALSE(doc.contains("label_recall"));
}

TEST(MapEvalApp, MainWritesEvalJsonAndReturnsInputErrorsAsExitCode2) {
  const MapEvalArgs args = writeWorld(world(), "main");
  const std::vector<std::string> argv_s = {"map-eval",       "--map", args.map_dir.string(), "--gt",
                                           args.gt.string(), "--out", args.out.string()};
  std::vector<const char*> argv;
  for (const auto& a : argv_s) {
    argv.push_back(a.c_str());
  }
  EXPECT_EQ(mapEvalMain(static_cast<int>(argv.size()), argv.data()), 0);
  std::ifstream in(args.out);
  EXPECT_EQ(json::parse(in)["matched_surfaces"], 2);
  std::ofstream(args.map_dir / "surfaces.csv", std::ios::app) << "5,0,0,1,0\n";
  EXPECT_EQ(mapEvalMain(static_cast<int>(argv.size()), argv.data()), 2);
}

// A voxel world's gt.json has poses but no surfaces or objects: what needs
// them is null, not a zero that reads as a perfect map.
TEST(MapEvalApp, GroundTruthWithoutObjectsGivesNullDistances) {
  SurfaceTestWorld w;
  for (int i = 0; i < 50; ++i) {
    w.addPoint({0.1 * i, 1.0, 0.5}, -1, -1);
  }
  const json doc = evaluateMap(writeWorld(w, "no_objects", false));
  EXPECT_LT(doc["pose_ate_m"].get<double>(), 1e-9);
  EXPECT_EQ(doc["label_check"]["labelled"], 0);
  EXPECT_TRUE(doc["label_check"]["fraction_within_3sigma"].is_null());
  ASSERT_FALSE(doc["octomap"].empty());
  for (const json& o : doc["octomap"]) {
    EXPECT_TRUE(o["mean_error_m"].is_null());
    EXPECT_TRUE(o["map_to_gt_mean_error_m"].is_null());
    EXPECT_GT(o["occupied_voxels"].get<int>(), 0);
  }
}

TEST(MapEvalApp, InconsistentMapFilesAreInputErrors) {
  SurfaceTestWorld w = world();
  w.surfaces.pop_back();  // points still carry surface id 1
  EXPECT_THROW(evaluateMap(writeWorld(w, "unknown_id")), InputError);
  const MapEvalArgs args = writeWorld(world(), "no_points");
  fs::remove(args.map_dir / "points.ply");
  EXPECT_THROW(evaluateMap(args), InputError);
}

// --- Issue 13: item 11 (the OctoMap baselines as .bt files) and item 12
// (never over an input; directories and non-finite numbers are input errors).

struct AppRun {
  int exit_code = -1;
  std::string err;  ///< what map-eval printed on stderr
};

AppRun runMapEval(const std::vector<std::string>& args) {
  std::vector<const char*> argv = {"map-eval"};
  for (const auto& a : args) {
    argv.push_back(a.c_str());
  }
  ::testing::internal::CaptureStderr();
  const int code = mapEvalMain(static_cast<int>(argv.size()), argv.data());
  return {code, ::testing::internal::GetCapturedStderr()};
}

std::vector<std::string> cli(const MapEvalArgs& a) {
  return {"--map", a.map_dir.string(), "--gt", a.gt.string(), "--out", a.out.string(), "-q"};
}

std::string fileBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// One error line naming `fragment`, as doc/errors.md promises.
void expectOneErrorLine(const AppRun& run, const std::string& fragment) {
  EXPECT_EQ(run.err.rfind("map-eval: error: ", 0), 0u) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_NE(run.err.find(fragment), std::string::npos) << run.err;
}

/// Occupied voxels of a tree at its resolution (pruned leaves expanded).
std::size_t occupiedVoxels(const octomap::OcTree& tree) {
  std::size_t n = 0;
  for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
    if (tree.isNodeOccupied(*it)) {
      const auto k = static_cast<std::size_t>(std::lround(it.getSize() / tree.getResolution()));
      n += k * k * k;
    }
  }
  return n;
}

// A --cloud map has no poses.txt: scored as it stands, its points labelled
// by the nearest object; the same surface scores as with the beams' labels.
TEST(MapEvalApp, Issue16_AMapWithoutPosesIsScoredAsItStands) {
  const MapEvalArgs args = writeWorld(world(), "cloud");
  fs::remove(args.map_dir / "poses.txt");
  const json doc = evaluateMap(args);
  EXPECT_TRUE(doc["pose"].is_null());
  EXPECT_FALSE(doc.contains("pose_ate_m"));
  EXPECT_FALSE(doc.contains("label_check"));
  EXPECT_FALSE(doc.contains("octomap"));
  EXPECT_NEAR(doc["labels"]["max_distance_m"].get<double>(), 0.03, 1e-12);  // 3 sigma
  EXPECT_EQ(doc["matched_surfaces"], 2);
  // Points on two objects at once go to the lower id: the floor's row on the
  // wall's foot is the wall's, the bin's point at z = 0 the floor's. Every
  // other point keeps its beam's label.
  EXPECT_GT(doc["label_recall"].get<double>(), 0.95);
  EXPECT_GT(doc["label_precision"].get<double>(), 0.95);
  EXPECT_EQ(doc["clutter_points"], 39);
  // A map of several scans without poses.txt lost it: an input error.
  SurfaceTestWorld two_scans = world();
  two_scans.points.scan.back() = 1;
  const MapEvalArgs lost = writeWorld(two_scans, "cloud_lost_poses");
  fs::remove(lost.map_dir / "poses.txt");
  EXPECT_THROW(evaluateMap(lost), InputError);
  fs::remove(args.map_dir / "points.ply");
  EXPECT_THROW(evaluateMap(args), InputError);
}

TEST(MapEvalApp, Item11_WritesOctomapBaselines) {
  MapEvalArgs args = writeWorld(world(), "item11");
  args.out = args.map_dir / "eval.json";  // the usual place: allowed
  const AppRun run = runMapEval(cli(args));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const json doc = json::parse(fileBytes(args.out));
  ASSERT_EQ(doc["octomap"].size(), 2u);
  const std::pair<std::string, double> expected[] = {{"octomap_5cm.bt", 0.05},
                                                     {"octomap_10cm.bt", 0.10}};
  for (std::size_t k = 0; k < 2; ++k) {
    const json& e = doc["octomap"][k];
    const fs::path bt = args.map_dir / expected[k].first;
    EXPECT_EQ(e["bt_file"], bt.string());
    ASSERT_TRUE(fs::is_regular_file(bt)) << bt;
    EXPECT_EQ(fs::file_size(bt), e["file_bytes"].get<std::uintmax_t>());
    octomap::OcTree tree(1.0);  // what octovis does with a .bt file
    ASSERT_TRUE(tree.readBinary(bt.string())) << bt;
    EXPECT_DOUBLE_EQ(tree.getResolution(), expected[k].second);
    EXPECT_GT(tree.size(), 0u);
    EXPECT_EQ(occupiedVoxels(tree), e["occupied_voxels"].get<std::size_t>());
  }
  for (const auto& entry : fs::directory_iterator(args.map_dir)) {
    EXPECT_EQ(entry.path().string().find(".tmp-"), std::string::npos) << entry.path();
  }
}

TEST(MapEvalApp, Item11_WithoutOutEverythingGoesToTheCurrentDirectory) {
  const MapEvalArgs args = writeWorld(world(), "item11_no_out");
  const fs::path cwd = fs::current_path();
  const fs::path here = args.map_dir.parent_path() / "cwd";
  fs::create_directories(here);
  fs::current_path(here);
  const AppRun run = runMapEval({"--map", args.map_dir.string(), "--gt", args.gt.string(), "-q"});
  fs::current_path(cwd);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(fs::is_regular_file(here / "eval.json"));
  EXPECT_TRUE(fs::is_regular_file(here / "octomap_5cm.bt"));
  EXPECT_TRUE(fs::is_regular_file(here / "octomap_10cm.bt"));
  EXPECT_EQ(json::parse(fileBytes(here / "eval.json"))["octomap"][0]["bt_file"], "octomap_5cm.bt");
}

TEST(MapEvalApp, Item12_RefusesToOverwriteGroundTruth) {
  MapEvalArgs args = writeWorld(world(), "item12_gt");
  const std::string before = fileBytes(args.gt);
  args.out = args.gt;
  const AppRun run = runMapEval(cli(args));
  EXPECT_EQ(run.exit_code, 4);
  expectOneErrorLine(run, "would overwrite the input file " + args.gt.string());
  EXPECT_EQ(fileBytes(args.gt), before);
  EXPECT_FALSE(fs::exists(args.gt.parent_path() / "octomap_5cm.bt"));
}

TEST(MapEvalApp, Item12_RefusesToOverwriteTheMapFilesItReads) {
  for (const std::string name : {"poses.txt", "points.ply", "scans.csv", "surfaces.csv"}) {
    MapEvalArgs args = writeWorld(world(), "item12_map");
    const fs::path input = args.map_dir / name;
    const std::string before = fileBytes(input);
    args.out = input;
    const AppRun run = runMapEval(cli(args));
    EXPECT_EQ(run.exit_code, 4) << name;
    expectOneErrorLine(run, "the input file " + input.string());
    EXPECT_EQ(fileBytes(input), before) << name;
    EXPECT_FALSE(fs::exists(args.map_dir / "octomap_5cm.bt")) << name;
  }
}

TEST(MapEvalApp, Item12_BtFilesNeverReplaceAnInput) {
  MapEvalArgs args = writeWorld(world(), "item12_bt");
  const fs::path gt = args.gt.parent_path() / "octomap_10cm.bt";  // a ground truth so named
  fs::rename(args.gt, gt);
  args.gt = gt;
  const std::string before = fileBytes(gt);
  const AppRun run = runMapEval(cli(args));  // --out beside it
  EXPECT_EQ(run.exit_code, 4);
  expectOneErrorLine(run, "(written beside --out) would overwrite the input file " + gt.string());
  EXPECT_EQ(fileBytes(gt), before);
  EXPECT_FALSE(fs::exists(args.out));
  EXPECT_FALSE(fs::exists(gt.parent_path() / "octomap_5cm.bt"));
}

TEST(MapEvalApp, Item12_LinksAndDirectoriesAsOutAreRefused) {
  MapEvalArgs args = writeWorld(world(), "item12_links");
  const std::string before = fileBytes(args.map_dir / "poses.txt");
  fs::create_symlink(args.map_dir / "poses.txt", args.map_dir / "eval.json");
  args.out = args.map_dir / "eval.json";
  EXPECT_EQ(runMapEval(cli(args)).exit_code, 4);
  fs::remove(args.out);
  args.out = args.map_dir / ".." / "map" / "poses.txt";
  EXPECT_EQ(runMapEval(cli(args)).exit_code, 4);
  args.out = args.map_dir;
  const AppRun run = runMapEval(cli(args));
  EXPECT_EQ(run.exit_code, 4);
  expectOneErrorLine(run, "--out is a directory");
  EXPECT_EQ(fileBytes(args.map_dir / "poses.txt"), before);
}

TEST(MapEvalApp, Item12_DirectoryAsGtIsInputError) {
  MapEvalArgs args = writeWorld(world(), "item12_gt_dir");
  args.gt = args.map_dir.parent_path() / "gt_dir";
  fs::create_directories(args.gt);
  const AppRun run = runMapEval(cli(args));
  EXPECT_EQ(run.exit_code, 2);
  expectOneErrorLine(run, args.gt.string() + ": is a directory, not a file");
}

TEST(MapEvalApp, Item12_DirectoryAsAMapFileIsInputError) {
  for (const std::string name :
       {"poses.txt", "points.ply", "scans.csv", "surfaces.csv", "map.glb", "raw.glb"}) {
    const MapEvalArgs args = writeWorld(world(), "item12_map_dir");
    const fs::path file = args.map_dir / name;
    fs::remove(file);
    fs::create_directories(file);
    const AppRun run = runMapEval(cli(args));
    EXPECT_EQ(run.exit_code, 2) << name;
    expectOneErrorLine(run, file.string() + ": ");
  }
  MapEvalArgs args = writeWorld(world(), "item12_map_is_a_file");
  args.map_dir = args.gt;
  const AppRun run = runMapEval(cli(args));
  EXPECT_EQ(run.exit_code, 2);
  expectOneErrorLine(run, args.gt.string() + ": not a directory");
}

TEST(MapEvalApp, Item12_NanInPointsPlyIsInputError) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const struct {
    int vertex, axis;
    double value;
    std::string message;
  } cases[] = {{7, 0, nan, "vertex 7: x is nan"}, {3, 2, -inf, "vertex 3: z is -inf"}};
  for (const auto& c : cases) {
    SurfaceTestWorld w = world();
    w.points.xyz[c.vertex][c.axis] = c.value;
    const MapEvalArgs args = writeWorld(w, "item12_nan");
    const AppRun run = runMapEval(cli(args));
    EXPECT_EQ(run.exit_code, 2) << c.message;
    expectOneErrorLine(run, (args.map_dir / "points.ply").string() + ": " + c.message);
    EXPECT_FALSE(fs::exists(args.out));
  }
}

/// The line of `text` (1-based) holding `needle`.
int lineOf(const std::string& text, const std::string& needle) {
  const std::size_t at = text.find(needle);
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

TEST(MapEvalApp, Item12_NonFiniteNumbersInEveryInputAreInputErrors) {
  {  // gt.json: the parser refuses 1e999; the message gives the line
    const MapEvalArgs args = writeWorld(world(), "item12_gt_inf");
    std::string text = json::parse(fileBytes(args.gt)).dump(2);
    const std::size_t at = text.find("\"sigma_m\": 0.01");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 15, "\"sigma_m\": 1e999");
    std::ofstream(args.gt) << text;
    const AppRun run = runMapEval(cli(args));
    EXPECT_EQ(run.exit_code, 2);
    expectOneErrorLine(
        run, args.gt.string() + ":" + std::to_string(lineOf(text, "1e999")) + ": not valid JSON: ");
  }
  const struct {
    std::string file, line, message;
  } rows[] = {
      {"poses.txt", "20.0 nan 0 0 0 0 0\n", "poses.txt:4: 'nan' is not a finite number"},
      {"surfaces.csv", "7,0,0,1,inf,0,0,0,1,0,0,1,1,0,0,1,0,5\n",
       "surfaces.csv:4: column 5 'inf' is not a finite number"},
      {"scans.csv", "1,2.0,LASER_V,5,nan,1\n",
       "scans.csv:3: column 5 'nan' is not a finite number"},
  };
  for (const auto& r : rows) {
    const MapEvalArgs args = writeWorld(world(), "item12_csv_nan");
    std::ofstream(args.map_dir / r.file, std::ios::app) << r.line;
    const AppRun run = runMapEval(cli(args));
    EXPECT_EQ(run.exit_code, 2) << r.file;
    expectOneErrorLine(run, r.message);
  }
  {  // raw.glb with a NaN vertex
    const MapEvalArgs args = writeWorld(world(), "item12_glb_nan");
    products::MapModel m;
    m.fine.vertices = {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(2, 0, 0),
                       Eigen::Vector3d(1, 0, 123.25)};
    m.fine.triangles = {{0, 1, 2}};
    ASSERT_TRUE(pmap::testing::writeGlbWithNan(m, 123.25f, args.map_dir / "raw.glb"));
    const AppRun run = runMapEval(cli(args));
    EXPECT_EQ(run.exit_code, 2);
    expectOneErrorLine(run, "raw.glb: accessor ");
    expectOneErrorLine(run, "POSITION 2 is not finite");
  }
}

// --- Issue 14: map-eval reads only the files the run's manifest lists, and
// only when they match it.

/// writeWorld() with the manifest planar-mapper would have written.
MapEvalArgs writeWorldWithManifest(const std::string& name) {
  const MapEvalArgs args = writeWorld(world(), name);
  products::writeManifest(args.map_dir, products::OutputManifest{});
  return args;
}

TEST(MapEvalApp, Item14_ReadsAFolderThatMatchesItsManifestWithoutWarning) {
  const MapEvalArgs args = writeWorldWithManifest("item14_match");
  const AppRun run = runMapEval(cli(args));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  EXPECT_EQ(json::parse(fileBytes(args.out))["matched_surfaces"], 2);
  // Its own outputs beside the map are exempt: a second evaluation into the
  // folder (eval.json, octomap_*.bt there) reads the same map.
  MapEvalArgs inside = args;
  inside.out = args.map_dir / "eval.json";
  EXPECT_EQ(runMapEval(cli(inside)).exit_code, 0);
  EXPECT_EQ(runMapEval(cli(inside)).exit_code, 0);
}

TEST(MapEvalApp, Item14_RefusesAFolderWhoseFilesDoNotMatchItsManifest) {
  const std::pair<std::string, std::string> cases[] = {
      {"poses.txt", "SHA-256 differs"},  // same size, other bytes
      {"surfaces.csv", "bytes, the manifest says"},
      {"scans.csv", "but missing"}};
  for (const auto& [file, fragment] : cases) {
    const MapEvalArgs args = writeWorldWithManifest("item14_" + file);
    const fs::path path = args.map_dir / file;
    if (file == "poses.txt") {
      std::string text = fileBytes(path);
      text[text.size() - 2] = '1';  // "... 0 0\n" -> "... 0 1\n"
      std::ofstream(path, std::ios::binary) << text;
    } else if (file == "surfaces.csv") {
      std::ofstream(path, std::ios::app) << "\n";
    } else {
      fs::remove(path);
    }
    const AppRun run = runMapEval(cli(args));
    EXPECT_EQ(run.exit_code, 2) << file;
    expectOneErrorLine(run, path.string() + ": ");
    expectOneErrorLine(run, fragment);
    EXPECT_FALSE(fs::exists(args.out)) << file;
  }
}

// A file the manifest does not list is never read: here the surfaces.csv of
// an earlier run, left beside a map whose run wrote none.
TEST(MapEvalApp, Item14_FilesTheManifestDoesNotListAreNotRead) {
  const MapEvalArgs args = writeWorld(world(), "item14_unlisted", /*with_csv=*/false);
  products::writeManifest(args.map_dir, products::OutputManifest{});
  writeSurfacesCsv(world().surfaces, args.map_dir / "surfaces.csv");
  const json doc = evaluateMap(args);
  EXPECT_TRUE(doc.contains("label_check"));
  EXPECT_FALSE(doc.contains("matched_surfaces"));
  EXPECT_FALSE(doc.contains("planar_map"));
}

TEST(MapEvalApp, Item14_AFolderWithoutManifestIsReadWithOneWarning) {
  const MapEvalArgs args = writeWorld(world(), "item14_legacy");
  const AppRun run = runMapEval(cli(args));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_EQ(run.err.rfind("map-eval: warning: " + args.map_dir.string() + ": no manifest.json", 0),
            0u)
      << run.err;
  EXPECT_EQ(json::parse(fileBytes(args.out))["matched_surfaces"], 2);
}

TEST(MapEvalApp, Item14_AMalformedManifestIsAnInputError) {
  const MapEvalArgs args = writeWorld(world(), "item14_bad_manifest");
  std::ofstream(args.map_dir / "manifest.json") << "{\"format\": \"planar-mapper-manifest\"}";
  const AppRun run = runMapEval(cli(args));
  EXPECT_EQ(run.exit_code, 2);
  expectOneErrorLine(run, "manifest.json: manifest version");
}

// Every map file is read before the first OctoMap is built: a bad raw.glb
// is reported although the OctoMap baseline would fail too (points.ply's
// scan 0 has no row in scans.csv), and no .bt file is written.
TEST(MapEvalApp, Item14_MapFilesAreCheckedBeforeTheOctomapBaselines) {
  const MapEvalArgs args = writeWorld(world(), "item14_check_first");
  std::ofstream(args.map_dir / "scans.csv") << "scan,timestamp,label,x,y,z\n1,1.0,LASER_V,5,1,1\n";
  std::ofstream(args.map_dir / "raw.glb") << "not a glb";
  products::writeManifest(args.map_dir, products::OutputManifest{});
  const AppRun run = runMapEval(cli(args));
  EXPECT_EQ(run.exit_code, 2);
  expectOneErrorLine(run, (args.map_dir / "raw.glb").string() + ": ");
  EXPECT_FALSE(fs::exists(args.out));
  EXPECT_FALSE(fs::exists(args.out.parent_path() / "octomap_5cm.bt"));
}

TEST(MapEvalApp, Item14_OutNeverReplacesAFileOfTheRun) {
  const MapEvalArgs args = writeWorldWithManifest("item14_out");
  for (const char* name : {"viewer.html", "summary.json", "map.simplemap"}) {
    MapEvalArgs a = args;
    a.out = args.map_dir / name;
    const AppRun run = runMapEval(cli(a));
    EXPECT_EQ(run.exit_code, 4) << name;
    expectOneErrorLine(run, "a planar-mapper output of the map folder");
    EXPECT_FALSE(fs::exists(a.out)) << name;
  }
}

}  // namespace
}  // namespace pmap::eval

namespace pmap::eval {
namespace {

// --gt-octomap (issue 16 item 6): the world's wall written as the planar
// map's map.glb, scored against a tree whose occupied voxels lie just behind
// it; alone, beside --gt, and refused without either ground truth.
TEST(MapEvalApp, Issue16_ScoresTheMapAgainstAnOctomapsOccupiedVoxels) {
  MapEvalArgs args = writeWorld(world(), "voxel_gt");
  products::MapModel m;
  m.fine.vertices = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(10, 0, 0), Eigen::Vector3d(10, 0, 3),
                     Eigen::Vector3d(0, 0, 3)};
  m.fine.triangles = {{0, 1, 2}, {0, 2, 3}};
  products::writeMapGlb(args.map_dir / "map.glb", m, false);
  octomap::OcTree tree(0.1);  // the wall's voxels: y in [-0.1, 0), x in [0, 10), z in [0, 3)
  for (int i = 0; i < 100; ++i) {
    for (int k = 0; k < 30; ++k) {
      tree.updateNode(octomap::point3d(0.05f + 0.1f * i, -0.05f, 0.05f + 0.1f * k), true);
    }
  }
  const fs::path bt = args.map_dir.parent_path() / "wall.bt";
  ASSERT_TRUE(tree.writeBinary(bt.string()));

  const AppRun alone = runMapEval(
      {"--map", args.map_dir.string(), "--gt-octomap", bt.string(), "--out", args.out.string()});
  ASSERT_EQ(alone.exit_code, 0) << alone.err;
  json doc = json::parse(fileBytes(args.out));
  EXPECT_FALSE(doc.contains("pose_ate_m"));
  const json& v = doc["voxel_gt"];
  EXPECT_EQ(v["occupied_voxels"], 3000);
  EXPECT_DOUBLE_EQ(v["resolution_m"].get<double>(), 0.1);
  EXPECT_LT(v["map_to_voxels"]["mean_m"].get<double>(), 1e-6);  // on the voxels' face
  EXPECT_DOUBLE_EQ(v["coverage"].get<double>(), 1.0);           // centres 5 cm from the map

  std::vector<std::string> both = cli(args);
  both.insert(both.end(), {"--gt-octomap", bt.string()});
  const AppRun with_gt = runMapEval(both);
  ASSERT_EQ(with_gt.exit_code, 0) << with_gt.err;
  doc = json::parse(fileBytes(args.out));
  EXPECT_TRUE(doc.contains("pose_ate_m"));
  EXPECT_EQ(doc["voxel_gt"]["occupied_voxels"], 3000);

  const AppRun neither = runMapEval({"--map", args.map_dir.string(), "--out", args.out.string()});
  EXPECT_EQ(neither.exit_code, 1);
  expectOneErrorLine(neither, "--gt-octomap");
  std::ofstream(args.map_dir.parent_path() / "text.bt") << "not a tree\n";
  const AppRun bad =
      runMapEval({"--map", args.map_dir.string(), "--gt-octomap",
                  (args.map_dir.parent_path() / "text.bt").string(), "--out", args.out.string()});
  EXPECT_EQ(bad.exit_code, 2);
  expectOneErrorLine(bad, "not an OctoMap binary tree");
}

}  // namespace
}  // namespace pmap::eval
