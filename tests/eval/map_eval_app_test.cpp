// map-eval end to end on files: a synthetic gt.json and a map directory
// (poses.txt, points.ply, surfaces.csv) written by the test.
#include "pmap/eval/map_eval_app.h"

#include <gtest/gtest.h>

#include <fstream>

#include "pmap/common/error.h"
#include "pmap/common/ply.h"
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

TEST(MapEvalApp, InconsistentMapFilesAreInputErrors) {
  SurfaceTestWorld w = world();
  w.surfaces.pop_back();  // points still carry surface id 1
  EXPECT_THROW(evaluateMap(writeWorld(w, "unknown_id")), InputError);
  const MapEvalArgs args = writeWorld(world(), "no_points");
  fs::remove(args.map_dir / "points.ply");
  EXPECT_THROW(evaluateMap(args), InputError);
}

}  // namespace
}  // namespace pmap::eval
