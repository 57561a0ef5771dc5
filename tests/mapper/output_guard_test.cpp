// The overwrite guard and the output-folder check take their names from
// products::OutputLayout (issue 14): every name it lists is guarded.
#include "pmap/mapper/output_guard.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

#include "pmap/common/error.h"
#include "pmap/products/output_layout.h"
#include "rawlog_fixtures.h"

namespace pmap::mapper {
namespace {
namespace fs = std::filesystem;
using products::LayoutEntry;
using products::OutputLayout;

/// A file name of each entry (patterns instantiated).
std::string example(const LayoutEntry& e) {
  if (e.kind != LayoutEntry::Kind::kPattern) {
    return e.name;
  }
  std::string name = e.name;
  for (const char* token : {"<n>", "<x>"}) {
    for (std::size_t at; (at = name.find(token)) != std::string::npos;) {
      name.replace(at, 3, "5");
    }
  }
  return name;
}

void writeText(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
}

std::string errorOf(const MapperArgs& args) {
  try {
    checkOutputsSpareInputs(args);
  } catch (const OutputError& e) {
    return e.what();
  }
  return "";
}

// An input at any name of the layout (a folder's: inside it) is refused,
// whichever input it is.
TEST(OutputGuard, Item14_EveryNameOfTheLayoutIsGuarded) {
  const fs::path dir = testing::freshTestDir("output_guard_names");
  std::size_t checked = 0;
  for (const LayoutEntry& e : OutputLayout::entries()) {
    const fs::path input = e.kind == LayoutEntry::Kind::kDirectory
                               ? dir / "out" / e.name / "given.ini"
                               : dir / "out" / example(e);
    writeText(input, "an input\n");
    for (int role = 0; role < 4; ++role) {
      MapperArgs args;
      args.out = dir / "out";
      (role == 0   ? args.rawlog
       : role == 1 ? args.cloud
       : role == 2 ? args.poses
                   : args.config) = input;
      const std::string error = errorOf(args);
      EXPECT_NE(error.find("would overwrite the input file " + input.string()), std::string::npos)
          << e.name << " as input " << role << ": " << error;
    }
    fs::remove_all(dir / "out");
    ++checked;
  }
  EXPECT_EQ(checked, OutputLayout::entries().size());
}

TEST(OutputGuard, Item14_TemporariesTheLockAndTheFolderItselfAreGuarded) {
  const fs::path dir = testing::freshTestDir("output_guard_more");
  for (const fs::path& input :
       {dir / "out/map.3Dscene.tmp-123", dir / ".out.lock", dir / "out/report/em_per_scan.png"}) {
    writeText(input, "x");
    MapperArgs args;
    args.out = dir / "out";
    args.poses = input;
    EXPECT_NE(errorOf(args).find("would overwrite"), std::string::npos) << input;
  }
  writeText(dir / "log.rawlog", "x");
  MapperArgs args;
  args.out = dir / "log.rawlog";
  args.rawlog = dir / "log.rawlog";
  EXPECT_NE(errorOf(args).find("the output directory is the input file"), std::string::npos);
}

// Files the layout does not name are no outputs: never replaced (a run keeps
// them in place), so they are not refused as inputs.
TEST(OutputGuard, Item14_ForeignFilesAreNoOutputs) {
  const fs::path dir = testing::freshTestDir("output_guard_foreign");
  for (const char* name : {"log.rawlog", "notes/log.rawlog", "poses.txt.orig", "sub/poses.txt"}) {
    writeText(dir / "out" / name, "x");
    MapperArgs args;
    args.out = dir / "out";
    args.rawlog = dir / "out" / name;
    EXPECT_EQ(errorOf(args), "") << name;
  }
}

TEST(OutputGuard, Item14_ForeignEntriesOfAFolder) {
  const fs::path dir = testing::freshTestDir("output_guard_entries");
  const fs::path out = dir / "out";
  for (const char* name : {"poses.txt", "report/report.html", "report/notes.txt", "textures/a.png",
                           "textures/surface_1_0.png", "eval.json", "octomap_5cm.bt",
                           "mine/deep/x.txt", "log.rawlog", "map.glb.tmp-77"}) {
    writeText(out / name, "x");
  }
  EXPECT_EQ(foreignEntries(out),
            (std::vector<std::string>{"log.rawlog", "mine", "report/notes.txt", "textures/a.png"}));
}

TEST(OutputGuard, Item14_AFolderWithForeignFilesNeedsAManifest) {
  const fs::path dir = testing::freshTestDir("output_guard_folder");
  const fs::path out = dir / "out";
  EXPECT_NO_THROW(checkOutputFolder(out, "out"));  // not there yet
  writeText(out / "poses.txt", "an earlier run's");
  writeText(out / "report/report.html", "an earlier run's");
  EXPECT_NO_THROW(checkOutputFolder(out, "out"));  // only named files: an older output folder
  writeText(out / "log.rawlog", "the user's");
  writeText(out / "b.txt", "the user's");
  try {
    checkOutputFolder(out, "out");
    FAIL() << "accepted a folder with foreign files and no manifest";
  } catch (const OutputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("out: holds b.txt (and 1 more), which planar-mapper does not write, and "
                        "no manifest.json"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("nothing was deleted or moved"), std::string::npos) << what;
  }
  writeText(out / "manifest.json", "{}");  // an output folder: foreign files stay in place
  EXPECT_NO_THROW(checkOutputFolder(out, "out"));
  writeText(dir / "file", "x");
  EXPECT_THROW(checkOutputFolder(dir / "file", "file"), OutputError);
}

}  // namespace
}  // namespace pmap::mapper
