#include "pmap/common/staged_directory.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

#include "pmap/common/error.h"
#include "test_files.h"

namespace pmap {
namespace {
namespace fs = std::filesystem;
using testing::snapshot;
using testing::writeText;

fs::path tmpDir(const std::string& name) {
  return testing::processTestDir("staged_directory", name);
}

/// The names in `parent` other than `target`'s own.
std::vector<std::string> siblings(const fs::path& parent) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(parent)) {
    names.push_back(e.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

void writeOldSet(const fs::path& out) {
  writeText(out / "a.txt", "old a");
  writeText(out / "stale.txt", "old only");
  writeText(out / "report/page.html", "old page");
}

void writeNewSet(const fs::path& staging) {
  writeText(staging / "a.txt", "new a");
  writeText(staging / "report/page.html", "new page");
}

const std::map<std::string, std::string> kNewSet = {
    {"a.txt", "new a"}, {"report", "<dir>"}, {"report/page.html", "new page"}};

StagedDirectory::Hooks withoutExchange() {
  StagedDirectory::Hooks hooks;
  hooks.exchange = [](const fs::path&, const fs::path&, std::error_code& ec) {
    ec = std::make_error_code(std::errc::invalid_argument);  // as on a file system without it
  };
  return hooks;
}

TEST(StagedDirectory, Item14_FirstRunMovesTheStagingFolderIntoPlace) {
  const fs::path dir = tmpDir("first");
  StagedDirectory staged(dir / "out");
  EXPECT_EQ(staged.path(), dir / (".out.staging-" + std::to_string(::getpid())));
  writeNewSet(staged.path());
  EXPECT_TRUE(staged.commit().empty());
  EXPECT_EQ(snapshot(dir / "out"), kNewSet);
  EXPECT_EQ(siblings(dir), std::vector<std::string>{"out"});
}

TEST(StagedDirectory, Item14_TheWholeSetIsReplacedWithAndWithoutExchange) {
  for (const bool exchange : {true, false}) {
    const fs::path dir = tmpDir(exchange ? "exchange" : "renames");
    writeOldSet(dir / "out");
    StagedDirectory staged(dir / "out", exchange ? StagedDirectory::Hooks{} : withoutExchange());
    writeNewSet(staged.path());
    EXPECT_EQ(snapshot(dir / "out").at("stale.txt"), "old only");  // untouched until commit
    staged.commit();
    EXPECT_EQ(snapshot(dir / "out"), kNewSet) << exchange;  // stale.txt is gone
    EXPECT_EQ(siblings(dir), std::vector<std::string>{"out"}) << exchange;
  }
}

// What `keep` selects stays: the same inode, a link as a link, a folder with
// its content; at its path throughout.
TEST(StagedDirectory, Item14_KeptEntriesStayTheSameFiles) {
  for (const bool exchange : {true, false}) {
    const fs::path dir = tmpDir(exchange ? "keep_exchange" : "keep_renames");
    writeOldSet(dir / "out");
    writeText(dir / "out/notes.txt", "mine");
    writeText(dir / "out/report/my.txt", "mine too");
    writeText(dir / "out/data/deep/x.bin", "data");
    fs::create_symlink("notes.txt", dir / "out/link");
    struct stat before {};
    ASSERT_EQ(::stat((dir / "out/notes.txt").c_str(), &before), 0);
    StagedDirectory staged(dir / "out", exchange ? StagedDirectory::Hooks{} : withoutExchange());
    writeNewSet(staged.path());
    staged.commit([](const fs::path& rel) {
      const std::string r = rel.generic_string();
      return r == "notes.txt" || r == "report/my.txt" || r == "data" || r == "link";
    });
    std::map<std::string, std::string> expected = kNewSet;
    expected.insert({{"notes.txt", "mine"},
                     {"report/my.txt", "mine too"},
                     {"data", "<dir>"},
                     {"data/deep", "<dir>"},
                     {"data/deep/x.bin", "data"},
                     {"link", "mine"}});
    EXPECT_EQ(snapshot(dir / "out"), expected);
    struct stat after {};
    ASSERT_EQ(::stat((dir / "out/notes.txt").c_str(), &after), 0);
    EXPECT_EQ(after.st_ino, before.st_ino);
    EXPECT_TRUE(fs::is_symlink(dir / "out/link"));
    EXPECT_EQ(siblings(dir), std::vector<std::string>{"out"});
  }
}

// The three renames fail one at a time: the target keeps the old set, byte
// for byte, and nothing is left beside it.
TEST(StagedDirectory, Item14_FailureAtAnyRenameKeepsTheOldSet) {
  for (int fail_at = 0; fail_at < 3; ++fail_at) {
    const fs::path dir = tmpDir("fail_" + std::to_string(fail_at));
    writeOldSet(dir / "out");
    const auto old_set = snapshot(dir / "out");
    StagedDirectory::Hooks hooks = withoutExchange();
    int call = 0;
    hooks.rename = [&](const fs::path& from, const fs::path& to, std::error_code& ec) {
      if (call++ == fail_at) {
        ec = std::make_error_code(std::errc::io_error);
        return;
      }
      fs::rename(from, to, ec);
    };
    {
      StagedDirectory staged(dir / "out", hooks);
      writeNewSet(staged.path());
      try {
        staged.commit();
        FAIL() << "no error at rename " << fail_at;
      } catch (const OutputError& e) {
        EXPECT_NE(std::string(e.what()).find("nothing was replaced"), std::string::npos)
            << e.what();
      }
    }
    EXPECT_EQ(snapshot(dir / "out"), old_set) << fail_at;
    EXPECT_EQ(siblings(dir), std::vector<std::string>{"out"}) << fail_at;
  }
}

TEST(StagedDirectory, Item14_ExchangeErrorReplacesNothing) {
  const fs::path dir = tmpDir("exchange_error");
  writeOldSet(dir / "out");
  const auto old_set = snapshot(dir / "out");
  StagedDirectory::Hooks hooks;
  hooks.exchange = [](const fs::path&, const fs::path&, std::error_code& ec) {
    ec = std::make_error_code(std::errc::no_space_on_device);
  };
  {
    StagedDirectory staged(dir / "out", hooks);
    writeNewSet(staged.path());
    EXPECT_THROW(staged.commit(), OutputError);
  }
  EXPECT_EQ(snapshot(dir / "out"), old_set);
  EXPECT_EQ(siblings(dir), std::vector<std::string>{"out"});
}

TEST(StagedDirectory, Item14_NotCommittedRemovesTheStagingFolder) {
  const fs::path dir = tmpDir("abandoned");
  writeOldSet(dir / "out");
  const auto old_set = snapshot(dir / "out");
  {
    StagedDirectory staged(dir / "out");
    writeNewSet(staged.path());
  }
  EXPECT_EQ(snapshot(dir / "out"), old_set);
  EXPECT_EQ(siblings(dir), std::vector<std::string>{"out"});
}

// The states a crash (SIGKILL, power loss) can leave, made by hand.
TEST(StagedDirectory, Item14_RecoveryFinishesAnInterruptedSwap) {
  const fs::path dir = tmpDir("recover_ready");
  writeNewSet(dir / ".out.ready-123");  // between "target -> old" and "ready -> target"
  writeOldSet(dir / ".out.old-123");
  writeText(dir / ".out.staging-77/a.txt", "half written");
  writeText(dir / ".out.notes/keep.txt", "not ours");  // no pid suffix: not a leftover
  writeText(dir / ".out.staging-x1/keep.txt", "not ours either");
  const std::vector<std::string> notes = StagedDirectory::recover(dir / "out");
  EXPECT_EQ(snapshot(dir / "out"), kNewSet);
  EXPECT_EQ(siblings(dir), (std::vector<std::string>{".out.notes", ".out.staging-x1", "out"}));
  ASSERT_EQ(notes.size(), 3u);
  EXPECT_NE(notes[0].find("finished the swap"), std::string::npos) << notes[0];
}

TEST(StagedDirectory, Item14_RecoveryRestoresTheOldSetWhenNothingNewIsComplete) {
  const fs::path dir = tmpDir("recover_old");
  writeOldSet(dir / ".out.old-5");
  writeText(dir / ".out.staging-5/a.txt", "half written");
  const auto old_set = snapshot(dir / ".out.old-5");
  StagedDirectory::recover(dir / "out");
  EXPECT_EQ(snapshot(dir / "out"), old_set);
  EXPECT_EQ(siblings(dir), std::vector<std::string>{"out"});
}

TEST(StagedDirectory, Item14_RecoveryRemovesLeftoversBesideACompleteTarget) {
  const fs::path dir = tmpDir("recover_stale");
  writeOldSet(dir / "out");
  const auto old_set = snapshot(dir / "out");
  writeNewSet(dir / ".out.staging-999999");  // a SIGKILLed run
  writeNewSet(dir / ".out.ready-999998");    // killed before "target -> old"
  EXPECT_EQ(StagedDirectory::recover(dir / "out").size(), 2u);
  EXPECT_EQ(snapshot(dir / "out"), old_set);
  EXPECT_EQ(siblings(dir), std::vector<std::string>{"out"});
  EXPECT_TRUE(StagedDirectory::recover(dir / "out").empty());
}

TEST(StagedDirectory, Item14_MountPoints) {
  EXPECT_TRUE(isMountPoint("/"));
  EXPECT_TRUE(isMountPoint("/proc"));
  EXPECT_FALSE(isMountPoint(tmpDir("mount")));
}

}  // namespace
}  // namespace pmap
