#include "pmap/common/atomic_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "pmap/common/error.h"

namespace pmap {
namespace {
namespace fs = std::filesystem;

fs::path tmpDir(const std::string& name) {
  const fs::path dir = fs::path(PMAP_TEST_TMP_DIR) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string readAll(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(AtomicFile, WritesAndReplaces) {
  const auto dir = tmpDir("atomic_writes");
  writeTextFileAtomically(dir / "a.txt", "one");
  writeTextFileAtomically(dir / "a.txt", "two");
  EXPECT_EQ(readAll(dir / "a.txt"), "two");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(AtomicFile, FailedWriterKeepsTheGoodFile) {
  const auto dir = tmpDir("atomic_failed");
  writeTextFileAtomically(dir / "a.txt", "good");
  EXPECT_THROW(writeFileAtomically(dir / "a.txt",
                                   [](std::ostream& out) {
                                     out << "partial";
                                     throw OutputError("simulated failure");
                                   }),
               OutputError);
  EXPECT_EQ(readAll(dir / "a.txt"), "good");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(AtomicFile, UnwritableTargetIsAnOutputError) {
  EXPECT_THROW(writeTextFileAtomically("/proc/pmap-cannot-write/x.txt", "x"), OutputError);
  EXPECT_THROW(ensureWritableDirectory("/proc/pmap-cannot-create"), OutputError);
}

}  // namespace
}  // namespace pmap
