#include "pmap/input/rawlog_reader.h"

#include <gtest/gtest.h>

#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/serialization/CArchive.h>

#include <zlib.h>

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

// Issue 13, item 8: a file that does not start like an MRPT archive (a
// JSON file given as the rawlog) is "not a rawlog", not a corrupt record.
TEST(RawlogReader, Item8_JsonFileIsNotARawlog) {
  const auto dir = testing::freshTestDir("reader_json");
  std::ofstream(dir / "run.gt.json") << "{\n  \"world\": \"default\",\n  \"surfaces\": []\n}\n";
  const std::string error = errorOf(dir / "run.gt.json");
  EXPECT_NE(error.find("not a rawlog"), std::string::npos) << error;
  EXPECT_EQ(error.find("Exception"), std::string::npos) << error;
  // The same text gzip-compressed is still not a rawlog.
  const std::string text = "{ \"a\": 1 }";
  gzFile gz = gzopen((dir / "j.rawlog").c_str(), "wb");
  gzwrite(gz, text.data(), static_cast<unsigned>(text.size()));
  gzclose(gz);
  EXPECT_NE(errorOf(dir / "j.rawlog").find("not a rawlog"), std::string::npos);
}

// A gzip member holding `bytes` (zlib's deflate with the gzip wrapper).
std::string gzipMember(const std::string& bytes) {
  z_stream zs{};
  EXPECT_EQ(deflateInit2(&zs, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY), Z_OK);
  std::string out(deflateBound(&zs, static_cast<uLong>(bytes.size())) + 64, '\0');
  zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  zs.avail_in = static_cast<uInt>(bytes.size());
  zs.next_out = reinterpret_cast<Bytef*>(out.data());
  zs.avail_out = static_cast<uInt>(out.size());
  EXPECT_EQ(deflate(&zs, Z_FINISH), Z_STREAM_END);
  out.resize(zs.total_out);
  deflateEnd(&zs);
  return out;
}

// A plain fixture split at a record boundary into two gzip members.
struct TwoMembers {
  std::string first, second;
  std::size_t records = 0, records_in_first = 0;
};

TwoMembers twoMembers(const fs::path& dir) {
  FixtureOptions o;
  o.cycles = 10;
  o.gzip = false;
  testing::writeFixtureRawlog(dir / "plain.rawlog", o);
  std::ifstream in(dir / "plain.rawlog", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), {});
  RawlogReader reader(dir / "plain.rawlog");
  RawlogRecord r;
  std::vector<std::uint64_t> offsets;
  while (reader.next(r)) {
    offsets.push_back(r.offset);
  }
  TwoMembers m;
  m.records = offsets.size();
  m.records_in_first = offsets.size() / 2;
  const std::size_t cut = offsets[m.records_in_first];
  m.first = gzipMember(bytes.substr(0, cut));
  m.second = gzipMember(bytes.substr(cut));
  return m;
}

void writeBytes(const fs::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
}

// Issue 13, item 12: every member of a multi-member gzip is read, and damage
// to the second member is reported, not taken for a clean end.
TEST(RawlogReader, Item12_MultiMemberGzipIsReadToItsEnd) {
  const auto dir = testing::freshTestDir("reader_members");
  const TwoMembers m = twoMembers(dir);
  writeBytes(dir / "both.rawlog", m.first + m.second);
  EXPECT_EQ(countRecords(dir / "both.rawlog"), m.records);
}

TEST(RawlogReader, Item12_DamagedSecondMemberIsCorruption) {
  const auto dir = testing::freshTestDir("reader_member_damage");
  const TwoMembers m = twoMembers(dir);
  std::string second = m.second;
  second[0] = static_cast<char>(second[0] ^ 0x40);  // its magic byte
  writeBytes(dir / "bad.rawlog", m.first + second);
  const std::string error = errorOf(dir / "bad.rawlog");
  EXPECT_NE(error.find("corrupt gzip data (member 1: "), std::string::npos) << error;
  RawlogReaderOptions accept;
  accept.accept_truncated = true;
  EXPECT_FALSE(errorOf(dir / "bad.rawlog", accept).empty());  // corruption, not a truncation
}

TEST(RawlogReader, Item12_FileEndingOneByteIntoTheSecondMemberIsTruncated) {
  const auto dir = testing::freshTestDir("reader_member_cut");
  const TwoMembers m = twoMembers(dir);
  writeBytes(dir / "cut.rawlog", m.first + m.second.substr(0, 1));
  const std::string error = errorOf(dir / "cut.rawlog");
  EXPECT_NE(error.find("truncated"), std::string::npos) << error;
  RawlogReaderOptions accept;
  accept.accept_truncated = true;
  EXPECT_EQ(countRecords(dir / "cut.rawlog", accept), m.records_in_first);
}

}  // namespace
}  // namespace pmap::input
