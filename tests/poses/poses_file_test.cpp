#include "pmap/poses/poses_file.h"

#include <gtest/gtest.h>

#include <fstream>

#include "pmap/common/error.h"
#include "rawlog_fixtures.h"

namespace pmap::poses {
namespace {
using mrpt::math::TPose3D;

TEST(PosesFile, RoundTrips) {
  const auto dir = testing::freshTestDir("poses_roundtrip");
  Trajectory t;
  t.append(1767225600.123456, TPose3D(1.5, -2.25, 0.0, 0.5, 0.0, 0.0));
  t.append(1767225600.323456, TPose3D(1.6, -2.25, 0.0, -3.1, 0.01, -0.02));
  writePosesFile(dir / "poses.txt", t);
  const Trajectory r = readPosesFile(dir / "poses.txt");
  ASSERT_EQ(r.size(), 2u);
  EXPECT_NEAR(r.poses()[1].t, 1767225600.323456, 1e-6);
  EXPECT_NEAR(r.poses()[1].pose.yaw, -3.1, 1e-8);
  EXPECT_NEAR(r.poses()[1].pose.roll, -0.02, 1e-8);
}

std::string errorOf(const std::string& text) {
  const auto dir = testing::freshTestDir("poses_bad");
  std::ofstream(dir / "p.txt") << text;
  try {
    readPosesFile(dir / "p.txt");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(PosesFile, RejectsMalformedFilesNamingTheLine) {
  EXPECT_NE(errorOf("# c\n1 2 3\n").find("p.txt:2: expected 7 numbers"), std::string::npos);
  EXPECT_NE(errorOf("1 0 0 0 nan 0 0\n").find("not a finite number"), std::string::npos);
  EXPECT_NE(errorOf("2 0 0 0 0 0 0\n1 0 0 0 0 0 0\n").find("p.txt:2: timestamp"),
            std::string::npos);
  EXPECT_NE(errorOf("1 0 0 0 0 0 0\n1 0 0 0 0 0 0\n").find("not after"), std::string::npos);
  EXPECT_NE(errorOf("# only a comment\n").find("no poses"), std::string::npos);
  EXPECT_THROW(readPosesFile("/nonexistent/poses.txt"), InputError);
}

}  // namespace
}  // namespace pmap::poses
