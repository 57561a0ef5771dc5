// What map-eval writes (issue 13, items 11 and 12): the evaluation file and
// the OctoMap .bt files beside it, never over an input file.
#include "pmap/eval/eval_outputs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>

#include "pmap/common/error.h"
#include "pmap/products/output_layout.h"
#include "pmap/products/output_manifest.h"

namespace pmap::eval {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

fs::path freshDir(const std::string& name) {
  const fs::path dir = fs::path(PMAP_TEST_TMP_DIR) / "eval_outputs" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string fileBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(EvalOutputs, Item11_OutputPathsAreOutAndTheBtFilesBesideIt) {
  EXPECT_EQ(outputPaths("m/eval.json", {0.05, 0.10}),
            (std::vector<fs::path>{"m/eval.json", "m/octomap_5cm.bt", "m/octomap_10cm.bt"}));
  EXPECT_EQ(outputPaths("eval.json", {0.05}),
            (std::vector<fs::path>{"eval.json", "octomap_5cm.bt"}));
}

TEST(EvalOutputs, Item11_WritesTheBtFilesThenEvalJsonNamingThem) {
  const fs::path dir = freshDir("write");
  json doc = {{"octomap", {{{"resolution_m", 0.05}, {"bt_file", "octomap_5cm.bt"}}}}};
  writeEvaluation(dir / "eval.json", {{"octomap_5cm.bt", std::string("bt\0bytes", 8)}}, doc);
  EXPECT_EQ(fileBytes(dir / "octomap_5cm.bt"), std::string("bt\0bytes", 8));
  const json back = json::parse(fileBytes(dir / "eval.json"));
  EXPECT_EQ(back["octomap"][0]["bt_file"], (dir / "octomap_5cm.bt").string());
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2);
}

TEST(EvalOutputs, Item11_AnUnwritableDirectoryIsAnOutputError) {
  json doc = json::object();
  EXPECT_THROW(writeEvaluation("/nonexistent/dir/eval.json", {{"octomap_5cm.bt", "x"}}, doc),
               OutputError);
}

TEST(EvalOutputs, Item12_AnOutputThatIsAnInputIsRefused) {
  const fs::path dir = freshDir("guard");
  fs::create_directories(dir / "map");
  std::ofstream(dir / "run.gt.json") << "{}";
  std::ofstream(dir / "map" / "poses.txt") << "0 0 0 0 0 0 0\n";
  const std::vector<fs::path> inputs = knownInputs(dir / "map", dir / "run.gt.json");
  const auto check = [&](const fs::path& out) {
    checkOutputsSpareInputs(outputPaths(out, {0.05, 0.10}), inputs);
  };
  EXPECT_NO_THROW(check(dir / "map" / "eval.json"));
  EXPECT_NO_THROW(check(dir / "map" / "points.ply"));  // not there: nothing to lose
  EXPECT_THROW(check(dir / "run.gt.json"), OutputError);
  EXPECT_THROW(check(dir / "map" / "poses.txt"), OutputError);
  EXPECT_THROW(check(dir / "map" / ".." / "run.gt.json"), OutputError);
  fs::create_hard_link(dir / "run.gt.json", dir / "hard.json");
  EXPECT_THROW(check(dir / "hard.json"), OutputError);
  fs::create_symlink(dir / "map" / "poses.txt", dir / "link.json");
  EXPECT_THROW(check(dir / "link.json"), OutputError);
  EXPECT_THROW(check(dir / "map"), OutputError);  // a directory
  // A .bt file beside --out that is an input.
  std::ofstream(dir / "octomap_5cm.bt") << "an input";
  EXPECT_THROW(
      checkOutputsSpareInputs(outputPaths(dir / "eval.json", {0.05}), {dir / "octomap_5cm.bt"}),
      OutputError);
}

TEST(EvalOutputs, Item12_TheMapFilesItReadsAreInputs) {
  const std::vector<fs::path> inputs = knownInputs("m", "g.json");
  EXPECT_EQ(inputs.front(), fs::path("g.json"));
  for (const char* name : {"poses.txt", "points.ply", "scans.csv", "surfaces.csv", "textures.csv",
                           "map.glb", "map-geometry.glb", "raw.glb"}) {
    EXPECT_NE(std::find(inputs.begin(), inputs.end(), fs::path("m") / name), inputs.end()) << name;
  }
}

// Issue 14: the names come from products::OutputLayout, the textures from the
// manifest; map-eval's outputs never replace a file of the run.
TEST(EvalOutputs, Item14_TheManifestsFilesAreInputsToo) {
  const fs::path dir = freshDir("manifest_inputs");
  std::ofstream(dir / "poses.txt") << "0 0 0 0 0 0 0\n";
  fs::create_directories(dir / "textures");
  std::ofstream(dir / "textures" / "surface_3_0.png") << "png";
  products::writeManifest(dir, products::OutputManifest{});
  const std::vector<fs::path> inputs = knownInputs(dir, "g.json");
  for (const char* name : {"manifest.json", "poses.txt", "textures/surface_3_0.png"}) {
    EXPECT_NE(std::find(inputs.begin(), inputs.end(), dir / name), inputs.end()) << name;
  }
  EXPECT_THROW(checkOutputsSpareInputs(outputPaths(dir / "textures/surface_3_0.png", {}), inputs),
               OutputError);
  for (const std::string& name : mapInputFileNames()) {
    EXPECT_TRUE(products::OutputLayout::names(name)) << name;
  }
}

TEST(EvalOutputs, Item14_OutputsNeverReplaceAFileOfTheRun) {
  const fs::path dir = freshDir("run_files");
  const auto check = [&](const fs::path& out) {
    checkOutputsSpareMapFiles(outputPaths(out, {0.05}), dir);
  };
  EXPECT_NO_THROW(check(dir / "eval.json"));
  EXPECT_NO_THROW(check(dir / "my-evaluation.json"));  // a name the layout does not know
  EXPECT_NO_THROW(check(dir / ".." / "eval.json"));    // not in the map folder
  for (const products::LayoutEntry& e : products::OutputLayout::entries()) {
    if (e.kind != products::LayoutEntry::Kind::kFile || e.name.find('/') != std::string::npos) {
      continue;
    }
    if (e.owner == products::LayoutEntry::Owner::kEvaluation) {
      EXPECT_NO_THROW(check(dir / e.name)) << e.name;
    } else {
      EXPECT_THROW(check(dir / e.name), OutputError) << e.name;
    }
  }
  EXPECT_THROW(check(dir / "." / "viewer.html"), OutputError);
}

}  // namespace
}  // namespace pmap::eval
