// Deterministic damage of every fixture rawlog (the synthetic fixtures in both
// formats, plain and gzip, and the bundled sample): truncation at 0/1/10/50/99
// %, seeded byte flips, and every length field of the first records set to a
// huge value. The reader must either read the file or throw one InputError
// whose one-line message names the file and the record; never crash, never
// let memory grow (peak RSS checked). With accept_truncated, a plain file cut
// after N complete records yields exactly those N records.
#include <gtest/gtest.h>
#include <zlib.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>

#include "asan.h"
#include "corruption.h"
#include "pmap/common/error.h"
#include "pmap/input/rawlog_reader.h"
#include "rawlog_fixtures.h"

namespace pmap::input {
namespace {
namespace fs = std::filesystem;
using testing::Bytes;

constexpr double kMaxPeakRssMiB = 1024.0;

struct Fixture {
  std::string name;
  fs::path path;
  bool gzip = false;
};

// The sample's bytes, decompressed (a plain rawlog of the same records).
void gunzip(const fs::path& src, const fs::path& dst) {
  gzFile in = gzopen(src.c_str(), "rb");
  ASSERT_NE(in, nullptr);
  Bytes out;
  char buf[65536];
  int n = 0;
  while ((n = gzread(in, buf, sizeof buf)) > 0) {
    out.insert(out.end(), buf, buf + n);
  }
  gzclose(in);
  testing::writeFileBytes(dst, out);
}

constexpr const char* kNames[] = {"obs_plain", "obs_gz",    "sf_plain",
                                  "sf_gz",     "sample_gz", "sample_plain"};

// Every fixture rawlog (in the order of kNames), written once per process.
const std::vector<Fixture>& fixtures() {
  static const std::vector<Fixture> all = [] {
    // Per process: CTest runs the tests of this file in parallel.
    const fs::path dir = testing::freshTestDir("corruption_fixtures/" + std::to_string(::getpid()));
    std::vector<Fixture> f;
    for (const auto format :
         {testing::FixtureFormat::kObservations, testing::FixtureFormat::kSensoryFrames}) {
      for (const bool gzip : {false, true}) {
        testing::FixtureOptions o;
        o.format = format;
        o.gzip = gzip;
        o.cycles = 12;
        const std::string name = kNames[f.size()];
        testing::writeFixtureRawlog(dir / (name + ".rawlog"), o);
        f.push_back({name, dir / (name + ".rawlog"), gzip});
      }
    }
    const fs::path sample = fs::path(PMAP_SOURCE_DIR) / "share/sample/default-L.rawlog";
    f.push_back({"sample_gz", sample, true});
    gunzip(sample, dir / "sample_plain.rawlog");
    f.push_back({"sample_plain", dir / "sample_plain.rawlog", false});
    return f;
  }();
  return all;
}

struct ReadOutcome {
  std::size_t records = 0;
  std::vector<std::uint64_t> ends;  ///< uncompressed offset after each record
  std::string error;                ///< InputError message, empty if none
  bool truncated = false;
};

ReadOutcome readAll(const fs::path& p, bool accept_truncated = false) {
  ReadOutcome r;
  RawlogReaderOptions o;
  o.accept_truncated = accept_truncated;
  try {
    RawlogReader reader(p, o);
    RawlogRecord rec;
    while (reader.next(rec)) {
      ++r.records;
      r.ends.push_back(reader.position());
    }
    r.truncated = reader.truncated();
  } catch (const InputError& e) {
    r.error = e.what();
  }
  return r;
}

// An InputError message: one line, naming the file (and the record once the
// file could be opened).
void expectOneLineError(const std::string& error, const fs::path& p) {
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  EXPECT_EQ(error.rfind(p.string() + ": ", 0), 0u) << error;
}

class Corruption : public ::testing::TestWithParam<std::size_t> {
 protected:
  const Fixture& fixture() const { return fixtures()[GetParam()]; }
  fs::path scratch(const std::string& what) const {
    const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    return testing::freshTestDir("corruption/" + test.substr(0, test.find('/')) + "/" +
                                 fixture().name) /
           (what + ".rawlog");
  }
};

TEST_P(Corruption, TruncationIsAnErrorOrAcceptedKeepingTheCompleteRecords) {
  const Fixture& f = fixture();
  const ReadOutcome intact = readAll(f.path);
  ASSERT_TRUE(intact.error.empty()) << intact.error;
  const fs::path cut = scratch("cut");
  for (const double fraction : {0.0, 0.01, 0.10, 0.50, 0.99}) {
    SCOPED_TRACE(f.name + " cut at " + std::to_string(fraction));
    testing::truncateCopy(f.path, cut, fraction);
    const std::uint64_t size = fs::file_size(cut);
    const ReadOutcome strict = readAll(cut);
    const ReadOutcome lenient = readAll(cut, true);
    // Complete records of a plain file: those ending at or before the cut.
    std::size_t complete = 0;
    while (complete < intact.ends.size() && intact.ends[complete] <= size) {
      ++complete;
    }
    const bool on_boundary =
        !f.gzip && size > 0 && complete > 0 && intact.ends[complete - 1] == size;
    if (on_boundary) {  // a plain file cut between records is a valid, shorter rawlog
      EXPECT_TRUE(strict.error.empty()) << strict.error;
      EXPECT_EQ(strict.records, complete);
      continue;
    }
    ASSERT_FALSE(strict.error.empty());
    expectOneLineError(strict.error, cut);
    if (size == 0) {
      EXPECT_NE(strict.error.find("empty file"), std::string::npos) << strict.error;
      continue;
    }
    EXPECT_TRUE(strict.error.find("truncated") != std::string::npos ||
                strict.error.find("not a rawlog") != std::string::npos)
        << strict.error;
    ASSERT_TRUE(lenient.error.empty()) << lenient.error;
    EXPECT_TRUE(lenient.truncated);
    if (f.gzip) {  // gzip decodes whole deflate blocks: fewer records may come out
      EXPECT_LE(lenient.records, intact.records);
    } else {
      EXPECT_EQ(lenient.records, complete);
    }
  }
  EXPECT_LT(testing::peakRssMiB(), kMaxPeakRssMiB);
}

TEST_P(Corruption, SeededByteFlipsAreReadOrReportedNeverACrash) {
  const Fixture& f = fixture();
  const Bytes original = testing::readFileBytes(f.path);
  const fs::path flipped = scratch("flipped");
  const std::size_t intact_records = readAll(f.path).records;
  for (std::uint32_t seed = 1; seed <= 24; ++seed) {
    Bytes b = original;
    testing::flipBytes(b, seed, 1 + static_cast<int>(seed % 4));
    testing::writeFileBytes(flipped, b);
    const ReadOutcome r = readAll(flipped);
    if (!r.error.empty()) {
      SCOPED_TRACE(f.name + " seed " + std::to_string(seed));
      expectOneLineError(r.error, flipped);
      EXPECT_NE(r.error.find("record "), std::string::npos) << r.error;
    } else {  // a harmless flip (a range, a pose): every record still there
      EXPECT_EQ(r.records, intact_records) << "seed " << seed;
    }
  }
  EXPECT_LT(testing::peakRssMiB(), kMaxPeakRssMiB);
}

// Every 4-byte window of the first records set to a huge length: MRPT would
// reserve up to 16 GiB for one scan; the reader refuses any single allocation
// above max_allocation_mb and reports corruption. The windows also cover the
// estimation method of the sf format's actions, on which MRPT itself crashes
// (guarded_classes.cpp). Length fields are edited in the plain fixtures (a
// gzip file's bytes are compressed: its plain twin holds the same records).
class LengthFields : public Corruption {};

TEST_P(LengthFields, HugeLengthFieldsKeepMemoryBounded) {
  const Fixture& f = fixture();
  ASSERT_FALSE(f.gzip);
  const ReadOutcome intact = readAll(f.path);
  ASSERT_GE(intact.ends.size(), 4u);
  const Bytes original = testing::readFileBytes(f.path);
  const fs::path edited = scratch("length");
  const std::size_t end = static_cast<std::size_t>(intact.ends[3]);  // records 0-3
  int refused = 0;
  int runs = 0;
  for (const std::uint32_t huge : {0xfffffff0u, 0x40000000u, 0x10000000u}) {
    for (std::size_t at = 0; at + 4 <= end; ++at) {
      Bytes b(original.begin(), original.begin() + static_cast<std::ptrdiff_t>(end));
      testing::putUint32(b, at, huge);
      testing::writeFileBytes(edited, b);
      const ReadOutcome r = readAll(edited);
      if (!r.error.empty()) {
        expectOneLineError(r.error, edited);
      }
      refused += r.error.find("size field") != std::string::npos ? 1 : 0;
      ++runs;
    }
  }
  RecordProperty("runs", runs);
  RecordProperty("refused", refused);
  std::printf("%d edited files, %d refused as too large\n", runs, refused);
  EXPECT_GT(refused, 0);  // at least the scan and label lengths were refused
  EXPECT_LT(testing::peakRssMiB(), kMaxPeakRssMiB);
}

// "Files larger than memory are streamed": one record at a time, so reading
// a long rawlog leaves the peak memory where writing it left it.
TEST(Streaming, PeakMemoryDoesNotGrowWithTheFile) {
#if PMAP_TEST_ASAN
  GTEST_SKIP() << "AddressSanitizer's quarantine keeps freed memory resident";
#endif
  const fs::path dir = testing::freshTestDir("streaming");
  testing::FixtureOptions o;
  o.gzip = false;
  o.cycles = 4000;  // 12000 records, about 13 MB
  testing::writeFixtureRawlog(dir / "long.rawlog", o);
  const double file_mib = static_cast<double>(fs::file_size(dir / "long.rawlog")) / (1 << 20);
  const double before = testing::peakRssMiB();
  const ReadOutcome r = readAll(dir / "long.rawlog");
  ASSERT_TRUE(r.error.empty()) << r.error;
  EXPECT_EQ(r.records, 12000u);
  EXPECT_LT(testing::peakRssMiB() - before, file_mib / 4) << "file " << file_mib << " MiB";
}

std::string fixtureName(const ::testing::TestParamInfo<std::size_t>& info) {
  return kNames[info.param];
}

INSTANTIATE_TEST_SUITE_P(EveryFixture, Corruption, ::testing::Range<std::size_t>(0, 6),
                         fixtureName);
// obs_plain, sf_plain, sample_plain.
INSTANTIATE_TEST_SUITE_P(PlainFixtures, LengthFields, ::testing::Values(0, 2, 5), fixtureName);

}  // namespace
}  // namespace pmap::input
