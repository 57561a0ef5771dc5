#include "pmap/products/output_folder.h"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>

#include "pmap/common/error.h"
#include "test_files.h"

namespace pmap::products {
namespace {
namespace fs = std::filesystem;
using testing::writeText;

fs::path tmpDir(const std::string& name) {
  return testing::processTestDir("output_folder", name);
}

/// A run's folder: poses.txt, points.ply and a texture, with its manifest.
fs::path writtenRun(const std::string& name) {
  const fs::path dir = tmpDir(name);
  writeText(dir / "poses.txt", "poses of run 2\n");
  writeText(dir / "points.ply", "points of run 2\n");
  writeText(dir / "textures/surface_1_0.png", "png");
  writeManifest(dir, OutputManifest{});
  return dir;
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no InputError";
}

TEST(OutputFolder, Item14_MatchingFilesAreReadAndUnlistedOnesAreNot) {
  const fs::path dir = writtenRun("matching");
  writeText(dir / "textures.csv", "left by run 1\n");  // not the run's: never read
  writeText(dir / "eval.json", "{}");                  // map-eval's own: exempt
  const OutputFolder folder(dir);
  EXPECT_TRUE(folder.hasManifest());
  EXPECT_TRUE(folder.warning().empty());
  EXPECT_NO_THROW(folder.verify());
  EXPECT_TRUE(folder.has("poses.txt"));
  EXPECT_TRUE(folder.has("textures/surface_1_0.png"));
  EXPECT_FALSE(folder.has("textures.csv"));
  EXPECT_FALSE(folder.has("surfaces.csv"));
  EXPECT_TRUE(folder.has("eval.json"));
  EXPECT_FALSE(folder.has("octomap_5cm.bt"));
  EXPECT_EQ(folder.file("poses.txt"), dir / "poses.txt");
  EXPECT_EQ(folder.file("eval.json"), dir / "eval.json");
  const std::string e = errorOf([&] { folder.file("textures.csv"); });
  EXPECT_NE(e.find("textures.csv: not in " + (dir / "manifest.json").string()), std::string::npos)
      << e;
}

TEST(OutputFolder, Item14_FilesThatDoNotMatchTheManifestAreRefusedByName) {
  {
    const fs::path dir = writtenRun("same_size");
    writeText(dir / "poses.txt", "poses of run 1\n");  // same size, other bytes
    const OutputFolder folder(dir);
    const std::string e = errorOf([&] { folder.verify(); });
    EXPECT_NE(e.find((dir / "poses.txt").string() + ": does not match"), std::string::npos) << e;
    EXPECT_NE(e.find("SHA-256 differs"), std::string::npos) << e;
  }
  {
    const fs::path dir = writtenRun("other_size");
    writeText(dir / "points.ply", "x\n");
    const std::string e = errorOf([&] { OutputFolder(dir).file("points.ply"); });
    EXPECT_NE(e.find("points.ply: does not match"), std::string::npos) << e;
    EXPECT_NE(e.find("2 bytes, the manifest says 16"), std::string::npos) << e;
  }
  {
    const fs::path dir = writtenRun("missing");
    fs::remove(dir / "textures/surface_1_0.png");
    const std::string e = errorOf([&] { OutputFolder(dir).verify(); });
    EXPECT_NE(e.find("surface_1_0.png: listed in"), std::string::npos) << e;
    EXPECT_NE(e.find("but missing"), std::string::npos) << e;
  }
}

TEST(OutputFolder, Item14_AFolderWithoutManifestIsReadAsBeforeWithAWarning) {
  const fs::path dir = tmpDir("legacy");
  writeText(dir / "poses.txt", "old\n");
  const OutputFolder folder(dir);
  EXPECT_FALSE(folder.hasManifest());
  EXPECT_NE(folder.warning().find("no manifest.json"), std::string::npos) << folder.warning();
  EXPECT_TRUE(folder.has("poses.txt"));
  EXPECT_FALSE(folder.has("points.ply"));
  EXPECT_EQ(folder.file("points.ply"), dir / "points.ply");  // unchecked; its reader reports it
  EXPECT_NO_THROW(folder.verify());
}

TEST(OutputFolder, Item14_AMalformedManifestIsAnInputError) {
  const fs::path dir = tmpDir("malformed");
  writeText(dir / "manifest.json", "[]");
  EXPECT_THROW(OutputFolder folder(dir), InputError);
}

}  // namespace
}  // namespace pmap::products
