#include "pmap/common/pid_lock.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <string>

namespace pmap {
namespace {
namespace fs = std::filesystem;

fs::path tmpDir(const std::string& name) {
  const fs::path dir = fs::path(PMAP_TEST_TMP_DIR) / "pid_lock" / name / std::to_string(::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(PidLock, Item14_HolderWritesItsPidAndRemovesTheFile) {
  const fs::path file = tmpDir("basic") / "out.lock";
  {
    PidLock lock(file);
    EXPECT_EQ(lock.stalePid(), 0);
    EXPECT_EQ(slurp(file), std::to_string(::getpid()) + "\n");
  }
  EXPECT_FALSE(fs::exists(file));
}

TEST(PidLock, Item14_SecondLockIsRefusedNamingTheHolder) {
  const fs::path file = tmpDir("held") / "out.lock";
  PidLock first(file);
  try {
    PidLock second(file);
    FAIL() << "the second lock was taken";
  } catch (const LockHeld& e) {
    EXPECT_EQ(e.holderPid(), ::getpid());
    EXPECT_EQ(e.exitCode(), 4);
    EXPECT_NE(std::string(e.what()).find("held by process " + std::to_string(::getpid())),
              std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(fs::exists(file));  // the refused one removed nothing
  first.release();
  EXPECT_FALSE(fs::exists(file));
  PidLock third(file);  // free again
  EXPECT_EQ(third.stalePid(), 0);
}

// A child takes the lock and is killed by SIGKILL: the kernel releases the
// flock, the file stays with the child's pid; the next lock takes it over
// and reports that pid.
TEST(PidLock, Item14_LockOfAKilledProcessIsTakenOver) {
  const fs::path file = tmpDir("killed") / "out.lock";
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    PidLock lock(file);
    const char c = 'x';
    (void)::write(ready[1], &c, 1);
    ::pause();
    ::_exit(0);
  }
  char c = 0;
  ASSERT_EQ(::read(ready[0], &c, 1), 1);
  EXPECT_THROW(PidLock busy(file), LockHeld);  // alive: held
  ::kill(child, SIGKILL);
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(fs::exists(file));  // SIGKILL: nobody removed it
  PidLock lock(file);
  EXPECT_EQ(lock.stalePid(), child);
  EXPECT_EQ(slurp(file), std::to_string(::getpid()) + "\n");
  ::close(ready[0]);
  ::close(ready[1]);
}

TEST(PidLock, Item14_UncreatableLockFileIsAnOutputError) {
  const fs::path file = tmpDir("uncreatable") / "no-such-dir" / "out.lock";
  try {
    PidLock lock(file);
    FAIL() << "no error";
  } catch (const LockHeld&) {
    FAIL() << "LockHeld for a missing directory";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("out.lock"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pmap
