#include "pmap/sim/output_paths.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include "pmap/common/error.h"
#include "sim_test_support.h"

namespace pmap::sim {
namespace {

TEST(OutputPaths, DerivedFromThePrefix) {
  const OutputPaths p = OutputPaths::fromPrefix("out/run1");
  EXPECT_EQ(p.rawlog, "out/run1.rawlog");
  EXPECT_EQ(p.images_dir, "out/run1_Images");
  EXPECT_EQ(p.gt_json, "out/run1.gt.json");
  EXPECT_EQ(p.poses_txt, "out/run1.poses.txt");
  EXPECT_EQ(p.images_dir_name, "run1_Images");
  EXPECT_EQ(OutputPaths::fromPrefix("out/run1.rawlog").rawlog, "out/run1.rawlog");
  EXPECT_THROW(OutputPaths::fromPrefix(""), ConfigError);
  EXPECT_THROW(OutputPaths::fromPrefix("out/"), ConfigError);
}

TEST(OutputPaths, Item12_StagedOutputsAreTemporariesCommittedTogether) {
  const auto dir = test::freshDir("staged");
  const OutputPaths p = OutputPaths::fromPrefix((dir / "run").string());
  const std::string pid = std::to_string(::getpid());
  std::filesystem::create_directories(p.images_dir);
  test::writeText(p.images_dir / "old.jpg", "old");
  {
    OutputSet set;
    const OutputPaths staged = p.stageIn(set);
    EXPECT_EQ(staged.rawlog, p.rawlog.string() + ".tmp-" + pid);
    EXPECT_EQ(staged.images_dir, p.images_dir.string() + ".tmp-" + pid);
    EXPECT_EQ(staged.gt_json, p.gt_json.string() + ".tmp-" + pid);
    EXPECT_EQ(staged.poses_txt, p.poses_txt.string() + ".tmp-" + pid);
    EXPECT_EQ(staged.images_dir_name, "run_Images");  // what the outputs refer to
    EXPECT_TRUE(std::filesystem::is_directory(staged.images_dir));
    test::writeText(staged.images_dir / "new.jpg", "new");
  }  // not committed: the old directory survives, the temporary one is gone
  const std::map<std::string, std::string> old_set = {
      {"run_Images", "<dir>"}, {"run_Images/old.jpg", test::fileEntry("old")}};
  EXPECT_EQ(test::snapshot(dir), old_set);
  {
    OutputSet set;
    const OutputPaths staged = p.stageIn(set);
    test::writeText(staged.images_dir / "new.jpg", "new");
    for (const auto& f : {staged.rawlog, staged.gt_json, staged.poses_txt}) {
      test::writeText(f, f.filename().string());
    }
    set.commit();
  }
  const std::map<std::string, std::string> new_set = {
      {"run_Images", "<dir>"},
      {"run_Images/new.jpg", test::fileEntry("new")},
      {"run.rawlog", test::fileEntry("run.rawlog.tmp-" + pid)},
      {"run.gt.json", test::fileEntry("run.gt.json.tmp-" + pid)},
      {"run.poses.txt", test::fileEntry("run.poses.txt.tmp-" + pid)}};
  EXPECT_EQ(test::snapshot(dir), new_set);
}

TEST(OutputPaths, Item12_ADirectoryAtAFileOutputIsRefusedBeforeAnyWork) {
  const auto dir = test::freshDir("wrong_kind");
  const OutputPaths p = OutputPaths::fromPrefix((dir / "run").string());
  std::filesystem::create_directories(p.rawlog / "keep");
  const auto before = test::snapshot(dir);
  {
    OutputSet set;
    try {
      p.stageIn(set);
      FAIL() << "no OutputError";
    } catch (const OutputError& e) {
      EXPECT_EQ(std::string(e.what()), p.rawlog.string() + ": exists and is a directory");
    }
  }
  EXPECT_EQ(test::snapshot(dir), before);
}

TEST(OutputPaths, UnwritableLocationIsAnOutputError) {
  const OutputPaths p = OutputPaths::fromPrefix("/proc/pmap-no-such-dir/run");
  OutputSet set;
  EXPECT_THROW(p.stageIn(set), OutputError);
}

}  // namespace
}  // namespace pmap::sim
