#include "pmap/common/output_set.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "pmap/common/error.h"

namespace pmap {
namespace {
namespace fs = std::filesystem;
using Kind = OutputSet::Kind;

fs::path tmpDir(const std::string& name) {
  // Per process: CTest runs the test cases of one binary in parallel.
  const fs::path dir =
      fs::path(PMAP_TEST_TMP_DIR) / "output_set" / name / std::to_string(::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void writeText(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

/// Every file and directory under `dir` (relative path -> content, "<dir>" for
/// directories).
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    std::ifstream in(e.path(), std::ios::binary);
    out[fs::relative(e.path(), dir).string()] =
        e.is_directory()
            ? "<dir>"
            : std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  return out;
}

/// A run's outputs: two files and a directory with one file.
void writeOutputs(const fs::path& a, const fs::path& images, const fs::path& b,
                  const std::string& tag) {
  writeText(a, "a " + tag);
  fs::create_directories(images);
  writeText(images / (tag + ".jpg"), "image " + tag);
  writeText(b, "b " + tag);
}

/// Adds the three outputs of `dir` to `set` and fills the temporaries.
void stageNewSet(OutputSet& set, const fs::path& dir) {
  const fs::path a = set.add(dir / "run.rawlog", Kind::kFile);
  const fs::path images = set.add(dir / "run_Images", Kind::kDirectory);
  const fs::path b = set.add(dir / "run.gt.json", Kind::kFile);
  writeOutputs(a, images, b, "new");
}

/// A rename that fails on its `fail_at`-th call (0-based) and on those in `also`.
OutputSet::RenameFunction failingRename(int* calls, int fail_at, std::vector<int> also = {}) {
  return [calls, fail_at, also](const fs::path& from, const fs::path& to, std::error_code& ec) {
    const int call = (*calls)++;
    if (call == fail_at || std::find(also.begin(), also.end(), call) != also.end()) {
      ec = std::make_error_code(std::errc::io_error);
      return;
    }
    fs::rename(from, to, ec);
  };
}

TEST(OutputSet, Item12_CommitReplacesTheWholeSet) {
  const fs::path dir = tmpDir("commit");
  writeOutputs(dir / "run.rawlog", dir / "run_Images", dir / "run.gt.json", "old");
  {
    OutputSet set;
    stageNewSet(set, dir);
    set.commit();
  }
  const std::map<std::string, std::string> expected = {{"run.rawlog", "a new"},
                                                       {"run_Images", "<dir>"},
                                                       {"run_Images/new.jpg", "image new"},
                                                       {"run.gt.json", "b new"}};
  EXPECT_EQ(snapshot(dir), expected);
}

TEST(OutputSet, Item12_UncommittedSetRemovesItsTemporaries) {
  const fs::path dir = tmpDir("uncommitted");
  writeOutputs(dir / "run.rawlog", dir / "run_Images", dir / "run.gt.json", "old");
  const auto before = snapshot(dir);
  {
    OutputSet set;
    stageNewSet(set, dir);
  }
  EXPECT_EQ(snapshot(dir), before);
}

// 3 outputs with an old set: 3 backups + 3 installs; fail each one in turn.
TEST(OutputSet, Item12_FailureAtAnyRenameKeepsTheOldSetWhole) {
  for (int fail_at = 0; fail_at < 6; ++fail_at) {
    SCOPED_TRACE("rename " + std::to_string(fail_at) + " fails");
    const fs::path dir = tmpDir("fail_old_" + std::to_string(fail_at));
    writeOutputs(dir / "run.rawlog", dir / "run_Images", dir / "run.gt.json", "old");
    const auto before = snapshot(dir);
    int calls = 0;
    OutputSet set(failingRename(&calls, fail_at));
    stageNewSet(set, dir);
    EXPECT_THROW(set.commit(), OutputError);
    EXPECT_EQ(snapshot(dir), before);
  }
}

TEST(OutputSet, Item12_FailureOnAFirstRunLeavesNothing) {
  for (int fail_at = 0; fail_at < 3; ++fail_at) {
    SCOPED_TRACE("rename " + std::to_string(fail_at) + " fails");
    const fs::path dir = tmpDir("fail_new_" + std::to_string(fail_at));
    int calls = 0;
    OutputSet set(failingRename(&calls, fail_at));
    stageNewSet(set, dir);
    EXPECT_THROW(set.commit(), OutputError);
    EXPECT_TRUE(fs::is_empty(dir));
  }
}

TEST(OutputSet, Item12_ErrorNamesTheTargetAndAFailedUndo) {
  const fs::path dir = tmpDir("failed_undo");
  writeOutputs(dir / "run.rawlog", dir / "run_Images", dir / "run.gt.json", "old");
  int calls = 0;
  // Calls 0-2 back up, 3-4 install; 5 (the gt.json install) fails, and so
  // does 6, the first undo (moving the new images back to their temporary).
  OutputSet set(failingRename(&calls, 5, {6}));
  stageNewSet(set, dir);
  try {
    set.commit();
    FAIL() << "no OutputError";
  } catch (const OutputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find((dir / "run.gt.json").string() + ": cannot move the new output"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("could not move " + (dir / "run_Images").string() + " back to"),
              std::string::npos)
        << what;
  }
  // Every other output was restored: the old rawlog and gt.json are back.
  EXPECT_EQ(snapshot(dir).at("run.rawlog"), "a old");
  EXPECT_EQ(snapshot(dir).at("run.gt.json"), "b old");
}

TEST(OutputSet, Item12_ARealRenameFailureKeepsTheOldSet) {
  const fs::path dir = tmpDir("real_failure");
  writeOutputs(dir / "run.rawlog", dir / "run_Images", dir / "run.gt.json", "old");
  // The backup name of run.gt.json is taken by a non-empty directory: moving
  // the file there fails (EISDIR) after the rawlog and the images moved aside.
  const fs::path blocker = dir / ("run.gt.json.old-" + std::to_string(::getpid()));
  fs::create_directories(blocker);
  writeText(blocker / "keep", "keep");
  const auto before = snapshot(dir);
  OutputSet set;
  stageNewSet(set, dir);
  EXPECT_THROW(set.commit(), OutputError);
  EXPECT_EQ(snapshot(dir), before);
}

TEST(OutputSet, Item12_ADirectoryWhereAFileGoesIsNeverReplaced) {
  const fs::path dir = tmpDir("wrong_kind");
  fs::create_directories(dir / "run.rawlog");
  writeText(dir / "run.rawlog" / "keep", "keep");
  writeText(dir / "run_Images", "a file");
  {
    OutputSet set;
    EXPECT_THROW(set.add(dir / "run.rawlog", Kind::kFile), OutputError);
    EXPECT_THROW(set.add(dir / "run_Images", Kind::kDirectory), OutputError);
  }
  // Made a directory after add(): commit() refuses it and restores the rest.
  fs::remove_all(dir);
  fs::create_directories(dir);
  writeOutputs(dir / "run.rawlog", dir / "run_Images", dir / "run.gt.json", "old");
  auto expected = snapshot(dir);
  expected["run.gt.json"] = "<dir>";
  expected["run.gt.json/keep"] = "keep";
  OutputSet set;
  stageNewSet(set, dir);
  fs::remove(dir / "run.gt.json");
  fs::create_directories(dir / "run.gt.json");
  writeText(dir / "run.gt.json" / "keep", "keep");
  try {
    set.commit();
    FAIL() << "no OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("run.gt.json: exists and is a directory"),
              std::string::npos);
  }
  EXPECT_EQ(snapshot(dir), expected);
}

}  // namespace
}  // namespace pmap
