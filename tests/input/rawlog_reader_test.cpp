#include "pmap/input/rawlog_reader.h"

#include <gtest/gtest.h>

#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/serialization/CArchive.h>

#include <fstream>

#include "pmap/common/error.h"
#include "rawlog_fixtures.h"

namespace pmap::input {
namespace {
namespace fs = std::filesystem;
using testing::FixtureFormat;
using testing::FixtureOptions;

std::size_t countRecords(const fs::path& p, RawlogReaderOptions o = {}) {
  RawlogReader reader(p, o);
  RawlogRecord r;
  std::size_t n = 0;
  while (reader.next(r)) {
    EXPECT_EQ(r.index, n);
    ++n;
  }
  return n;
}

std::string errorOf(const fs::path& p, RawlogReaderOptions o = {}) {
  try {
    countRecords(p, o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(RawlogReader, ReadsPlainAndGzipAlike) {
  const auto dir = testing::freshTestDir("reader_formats");
  FixtureOptions o;
  o.cycles = 5;
  testing::writeFixtureRawlog(dir / "a.rawlog", o);
  o.gzip = false;
  testing::writeFixtureRawlog(dir / "b.rawlog", o);
  EXPECT_EQ(countRecords(dir / "a.rawlog"), 15u);
  EXPECT_EQ(countRecords(dir / "b.rawlog"), 15u);
}

TEST(RawlogReader, KeepsTheLeadingSensoryFrame) {
  const auto dir = testing::freshTestDir("reader_leading");
  FixtureOptions o;
  o.format = FixtureFormat::kSensoryFrames;
  o.cycles = 3;
  o.leading_frame = true;
  testing::writeFixtureRawlog(dir / "sf.rawlog", o);
  EXPECT_EQ(countRecords(dir / "sf.rawlog"), 7u);  // leading frame + 3 x (action, frame)
}

TEST(RawlogReader, MissingEmptyDirectoryAndGarbageAreInputErrors) {
  const auto dir = testing::freshTestDir("reader_bad");
  EXPECT_NE(errorOf(dir / "missing.rawlog").find("not found"), std::string::npos);
  EXPECT_NE(errorOf(dir).find("is a directory"), std::string::npos);
  std::ofstream(dir / "empty.rawlog").close();
  EXPECT_NE(errorOf(dir / "empty.rawlog").find("empty file"), std::string::npos);
  std::ofstream(dir / "text.rawlog") << "this is not a rawlog, just some text\n";
  const std::string text_error = errorOf(dir / "text.rawlog");
  EXPECT_NE(text_error.find("record 0 at byte 0"), std::string::npos) << text_error;
}

// A plain (uncompressed) rawlog has no end marker: a file cut exactly between
// two records cannot be told from a complete one, so the fractions avoid the
// fixture's record boundaries (every 10 % is one). gzip files carry a trailer.
class Truncation : public ::testing::TestWithParam<std::tuple<bool, double>> {};

TEST_P(Truncation, IsAnErrorUnlessAcceptedThenKeepsCompleteRecords) {
  const auto [gzip, fraction] = GetParam();
  const auto dir = testing::freshTestDir("reader_truncated_" + std::to_string(gzip) + "_" +
                                         std::to_string(static_cast<int>(fraction * 100)));
  FixtureOptions o;
  o.gzip = gzip;
  o.cycles = 20;
  testing::writeFixtureRawlog(dir / "full.rawlog", o);
  testing::truncateCopy(dir / "full.rawlog", dir / "cut.rawlog", fraction);
  const std::string error = errorOf(dir / "cut.rawlog");
  EXPECT_NE(error.find("truncated"), std::string::npos) << error;
  EXPECT_NE(error.find("cut.rawlog: record "), std::string::npos) << error;

  RawlogReaderOptions accept;
  accept.accept_truncated = true;
  RawlogReader reader(dir / "cut.rawlog", accept);
  RawlogRecord r;
  std::size_t n = 0;
  while (reader.next(r)) {
    ++n;
  }
  EXPECT_TRUE(reader.truncated());
  EXPECT_LT(n, 60u);
  if (!gzip) {  // gzip decodes whole deflate blocks: a cut file may yield few records
    EXPECT_GE(n, static_cast<std::size_t>(fraction * 50));
  }
}

INSTANTIATE_TEST_SUITE_P(PlainAndGzip, Truncation,
                         ::testing::Combine(::testing::Bool(),
                                            ::testing::Values(0.13, 0.51, 0.99)));

TEST(RawlogReader, FlippedBytesInGzipAreCorruption) {
  const auto dir = testing::freshTestDir("reader_flip");
  FixtureOptions o;
  o.cycles = 20;
  testing::writeFixtureRawlog(dir / "full.rawlog", o);
  std::fstream f(dir / "full.rawlog", std::ios::in | std::ios::out | std::ios::binary);
  f.seekp(static_cast<std::streamoff>(fs::file_size(dir / "full.rawlog") / 2));
  const char junk[8] = {'\x5a', '\x00', '\x7f', '\x13', '\xff', '\x01', '\x42', '\x99'};
  f.write(junk, sizeof junk);
  f.close();
  const std::string error = errorOf(dir / "full.rawlog");
  EXPECT_FALSE(error.empty());
  EXPECT_NE(error.find("record "), std::string::npos) << error;
}

// The reader decodes CActionRobotMovement2D through its own guard
// (guarded_classes.cpp), which re-encodes what it checked for MRPT's
// decoder: both estimation methods must come back exactly.
TEST(RawlogReader, GuardedActionDecoderKeepsBothEstimationMethods) {
  using mrpt::obs::CActionRobotMovement2D;
  const auto dir = testing::freshTestDir("reader_actions");
  CActionRobotMovement2D odometry;
  odometry.computeFromOdometry(mrpt::poses::CPose2D(0.5, -0.25, 0.1),
                               CActionRobotMovement2D::TMotionModelOptions());
  CActionRobotMovement2D matched;
  matched.estimationMethod = CActionRobotMovement2D::emScan2DMatching;
  matched.poseChange = mrpt::poses::CPosePDFGaussian::Create(mrpt::poses::CPose2D(1.5, 2.0, -0.3));
  {
    mrpt::io::CFileOutputStream out((dir / "a.rawlog").string());
    auto arch = mrpt::serialization::archiveFrom(out);
    mrpt::obs::CActionCollection acts;
    acts.insert(odometry);
    acts.insert(matched);
    arch << acts;
  }
  RawlogReader reader(dir / "a.rawlog");
  RawlogRecord r;
  ASSERT_TRUE(reader.next(r));
  const auto acts = std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(r.object);
  ASSERT_TRUE(acts);
  ASSERT_EQ(acts->size(), 2u);
  const auto a0 = acts->getActionByClass<CActionRobotMovement2D>(0);
  const auto a1 = acts->getActionByClass<CActionRobotMovement2D>(1);
  ASSERT_TRUE(a0 && a1);
  EXPECT_EQ(a0->estimationMethod, CActionRobotMovement2D::emOdometry);
  EXPECT_NEAR(a0->rawOdometryIncrementReading.x(), 0.5, 1e-12);
  EXPECT_NEAR(a0->rawOdometryIncrementReading.phi(), 0.1, 1e-12);
  EXPECT_EQ(a1->estimationMethod, CActionRobotMovement2D::emScan2DMatching);
  EXPECT_NEAR(a1->poseChange->getMeanVal().x(), 1.5, 1e-12);
  EXPECT_NEAR(a1->poseChange->getMeanVal().phi(), -0.3, 1e-12);
  EXPECT_FALSE(reader.next(r));
}

}  // namespace
}  // namespace pmap::input
