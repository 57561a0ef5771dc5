// planar-mapper on damaged rawlogs: nothing lost with --accept-truncated (a
// file cut after N complete records gives exactly the map of those N records
// of the intact file), and byte flips give exit 2 with one line, or exit 0
// with a valid map when the flip lands somewhere harmless.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "app_runner.h"
#include "bad_input_support.h"
#include "corruption.h"
#include "pmap/input/rawlog_reader.h"
#include "pmap/mapper/planar_mapper_app.h"

namespace pmap::mapper {
namespace {
namespace fs = std::filesystem;

int run(const std::vector<std::string>& args) {
  return testing::runMain(&planarMapperMain, "planar-mapper", args);
}

std::string fileText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Complete records an accepting reader delivers from `p`.
std::size_t completeRecords(const fs::path& p) {
  input::RawlogReaderOptions o;
  o.accept_truncated = true;
  input::RawlogReader reader(p, o);
  input::RawlogRecord r;
  std::size_t n = 0;
  while (reader.next(r)) {
    ++n;
  }
  return n;
}

using NothingLostParam = std::tuple<testing::FixtureFormat, bool, double>;

std::string paramName(const NothingLostParam& p) {
  const bool obs = std::get<0>(p) == testing::FixtureFormat::kObservations;
  return std::string(obs ? "obs" : "sf") + (std::get<1>(p) ? "_gz_" : "_plain_") +
         std::to_string(static_cast<int>(std::get<2>(p) * 100));
}
class NothingLost : public ::testing::TestWithParam<NothingLostParam> {};

TEST_P(NothingLost, TruncatedAfterNRecordsGivesTheMapOfThoseNRecords) {
  const auto [format, gzip, fraction] = GetParam();
  const fs::path dir = testing::freshTestDir(
      "nothing_lost/" + std::to_string(static_cast<int>(format)) + std::to_string(gzip) + "_" +
      std::to_string(static_cast<int>(fraction * 100)));
  testing::FixtureOptions o;
  o.format = format;
  o.gzip = gzip;
  const fs::path full = testing::writeFixture(dir, o);
  testing::truncateCopy(full, dir / "cut.rawlog", fraction);
  const std::size_t n = completeRecords(dir / "cut.rawlog");
  ASSERT_GE(n, 12u) << "too few records to map";

  ASSERT_EQ(run({"--rawlog", (dir / "cut.rawlog").string(), "--out", (dir / "cut").string(), "-q",
                 "--accept-truncated"}),
            0);
  ASSERT_EQ(run({"--rawlog", full.string(), "--to-index", std::to_string(n - 1), "--out",
                 (dir / "head").string(), "-q"}),
            0);
  for (const char* file : {"poses.txt", "scans.csv", "points.ply", "surfaces.csv", "map.wrl"}) {
    EXPECT_EQ(fileText(dir / "cut" / file), fileText(dir / "head" / file)) << file;
  }
  EXPECT_FALSE(fileText(dir / "cut" / "points.ply").empty());
}

INSTANTIATE_TEST_SUITE_P(
    BothFormatsPlainAndGzip, NothingLost,
    ::testing::Combine(::testing::Values(testing::FixtureFormat::kObservations,
                                         testing::FixtureFormat::kSensoryFrames),
                       ::testing::Bool(), ::testing::Values(0.5, 0.99)),
    [](const ::testing::TestParamInfo<NothingLostParam>& info) { return paramName(info.param); });

// Seeded flips of a plain fixture through the whole program.
TEST(DamagedRawlog, ByteFlipsGiveExit2OrAValidMap) {
  const fs::path dir = testing::freshTestDir("damaged_rawlog_flips");
  testing::FixtureOptions o;
  o.gzip = false;
  const fs::path full = testing::writeFixture(dir, o);
  const testing::Bytes original = testing::readFileBytes(full);
  int valid_maps = 0;
  for (std::uint32_t seed = 1; seed <= 10; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    testing::Bytes b = original;
    testing::flipBytes(b, seed, 2);
    testing::writeFileBytes(dir / "flipped.rawlog", b);
    fs::remove_all(dir / "out");
    ::testing::internal::CaptureStderr();
    const int code = run(testing::mapArgs(dir / "flipped.rawlog", dir));
    const std::string err = ::testing::internal::GetCapturedStderr();
    ASSERT_TRUE(code == 0 || code == 2) << code << ": " << err;
    if (code == 0) {
      testing::expectValidMap(dir);
      ++valid_maps;
    } else {
      EXPECT_EQ(err.rfind("planar-mapper: error: ", 0), 0u) << err;
      EXPECT_EQ(err.find('\n'), err.size() - 1) << err;
      EXPECT_FALSE(fs::exists(dir / "out" / "points.ply"));
    }
  }
  RecordProperty("valid_maps", valid_maps);  // flips that landed in ranges or poses
  EXPECT_LT(testing::peakRssMiB(), 1024.0);
}

}  // namespace
}  // namespace pmap::mapper
