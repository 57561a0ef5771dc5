#include "pmap/products/output_layout.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <set>

namespace pmap::products {
namespace {

using Kind = LayoutEntry::Kind;
using Owner = LayoutEntry::Owner;

/// A file name of each entry (patterns instantiated).
std::string example(const LayoutEntry& e) {
  if (e.kind != Kind::kPattern) {
    return e.name;
  }
  if (e.name == "textures/surface_<n>_<n>.png") {
    return OutputLayout::textureFile(4, 1);
  }
  if (e.name == "textures/surface_<n>.png") {
    return OutputLayout::textureFile(12);
  }
  if (e.name == "snapshots/map_<n>.wrl") {
    return OutputLayout::snapshotFile(50);
  }
  if (e.name == "octomap_<x>cm.bt") {
    return OutputLayout::octomapFile(0.025);
  }
  ADD_FAILURE() << "no example for " << e.name;
  return e.name;
}

TEST(OutputLayout, Item14_EveryEntryAndItsTemporariesAreNamed) {
  std::set<std::string> seen;
  for (const LayoutEntry& e : OutputLayout::entries()) {
    EXPECT_TRUE(seen.insert(e.name).second) << "listed twice: " << e.name;
    const std::string name = example(e);
    EXPECT_TRUE(OutputLayout::names(name)) << name;
    EXPECT_EQ(OutputLayout::find(name), &e) << name;
    EXPECT_TRUE(OutputLayout::names(name + ".tmp-4711")) << name;
    EXPECT_TRUE(OutputLayout::names(name + ".old-12")) << name;
    EXPECT_FALSE(OutputLayout::names(name + ".bak")) << name;
    EXPECT_FALSE(e.what.empty()) << name;
  }
}

TEST(OutputLayout, Item14_NamesEveryFileOfTheIssueAndTheReservedOnes) {
  for (const char* name : {"effective.ini",
                           "summary.json",
                           "poses.txt",
                           "poses.tum",
                           "scans.csv",
                           "points.ply",
                           "raw.wrl",
                           "raw.glb",
                           "online.csv",
                           "surfaces.csv",
                           "map.wrl",
                           "map.glb",
                           "map-geometry.glb",
                           "textures.csv",
                           "frames.csv",
                           "viewer.html",
                           "map.3Dscene",
                           "manifest.json",
                           "report",
                           "report/report.html",
                           "report/map_perspective.png",
                           "report/map_top.png",
                           "report/em_iterations.png",
                           "report/em_per_scan.png",
                           "textures",
                           "textures/surface_5_0.png",
                           "snapshots",
                           "snapshots/map_000150.wrl",
                           "eval.json",
                           "octomap_5cm.bt",
                           "octomap_10cm.bt"}) {
    EXPECT_TRUE(OutputLayout::names(name)) << name;
  }
  for (const char* name : {"poses.graph", "grid.png", "grid.gridmap.gz", "map.simplemap"}) {
    const LayoutEntry* e = OutputLayout::find(name);
    ASSERT_NE(e, nullptr) << name;
    EXPECT_EQ(e->owner, Owner::kRun) << name;  // issue 15 item 6: written by the run
  }
}

TEST(OutputLayout, Item14_OtherFilesAreNotNamed) {
  for (const char* name :
       {"notes.txt", "log.rawlog", "report/notes.txt", "textures/poster.png",
        "textures/surface_x.png", "snapshots/map.wrl", "poses.txt.bak", "notes.txt.tmp-12",
        "octomap_cm.bt", "sub/poses.txt", "map.3Dscene.tmp-", ".planar-mapper"}) {
    EXPECT_FALSE(OutputLayout::names(name)) << name;
  }
  EXPECT_TRUE(OutputLayout::names("./poses.txt"));
  EXPECT_TRUE(OutputLayout::names("report/"));
}

TEST(OutputLayout, Item14_ManifestExemptions) {
  for (const char* name : {"manifest.json", "eval.json", "octomap_5cm.bt", "eval.json.tmp-3"}) {
    EXPECT_TRUE(OutputLayout::manifestExempt(name)) << name;
  }
  for (const char* name : {"points.ply", "textures/surface_1_0.png", "notes.txt", "poses.graph"}) {
    EXPECT_FALSE(OutputLayout::manifestExempt(name)) << name;
  }
}

TEST(OutputLayout, Item14_GeneratedNames) {
  EXPECT_EQ(OutputLayout::textureFile(4, 1), "textures/surface_4_1.png");
  EXPECT_EQ(OutputLayout::textureFile(7), "textures/surface_7.png");
  EXPECT_EQ(OutputLayout::snapshotFile(50), "snapshots/map_000050.wrl");
  EXPECT_EQ(OutputLayout::snapshotFile(1234567), "snapshots/map_1234567.wrl");
  EXPECT_EQ(OutputLayout::octomapFile(0.05), "octomap_5cm.bt");
  EXPECT_EQ(OutputLayout::octomapFile(0.10), "octomap_10cm.bt");
  EXPECT_EQ(OutputLayout::octomapFile(0.025), "octomap_2.5cm.bt");
}

// doc/outputs.md's layout table names every entry (in backquotes).
TEST(OutputLayout, Item14_TheDocListsEveryEntry) {
  std::ifstream in(std::string(PMAP_SOURCE_DIR) + "/doc/outputs.md");
  const std::string doc((std::istreambuf_iterator<char>(in)), {});
  ASSERT_FALSE(doc.empty());
  for (const LayoutEntry& e : OutputLayout::entries()) {
    const std::string shown = e.kind == Kind::kDirectory ? e.name + "/" : e.name;
    EXPECT_NE(doc.find("`" + shown + "`"), std::string::npos) << shown;
  }
}

}  // namespace
}  // namespace pmap::products
