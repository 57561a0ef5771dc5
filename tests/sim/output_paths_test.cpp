#include "pmap/sim/output_paths.h"

#include <gtest/gtest.h>

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

TEST(OutputPaths, ImagesDirectoryIsReplacedOnlyOnCommit) {
  const auto dir = test::freshDir("images_txn");
  const OutputPaths p = OutputPaths::fromPrefix((dir / "run").string());
  std::filesystem::create_directories(p.images_dir);
  test::writeText(p.images_dir / "old.jpg", "old");
  {
    ImagesDirTransaction txn(p);
    test::writeText(p.images_tmp_dir / "new.jpg", "new");
  }  // not committed: the old directory survives, the temporary one is gone
  EXPECT_TRUE(std::filesystem::exists(p.images_dir / "old.jpg"));
  EXPECT_FALSE(std::filesystem::exists(p.images_tmp_dir));
  {
    ImagesDirTransaction txn(p);
    test::writeText(p.images_tmp_dir / "new.jpg", "new");
    txn.commit();
  }
  EXPECT_TRUE(std::filesystem::exists(p.images_dir / "new.jpg"));
  EXPECT_FALSE(std::filesystem::exists(p.images_dir / "old.jpg"));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir),
                          std::filesystem::directory_iterator()),
            1);
}

TEST(OutputPaths, UnwritableLocationIsAnOutputError) {
  const OutputPaths p = OutputPaths::fromPrefix("/proc/pmap-no-such-dir/run");
  EXPECT_THROW(ImagesDirTransaction txn(p), OutputError);
}

}  // namespace
}  // namespace pmap::sim
