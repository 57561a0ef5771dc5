// planar-mapper on damaged rawlogs: nothing lost with --accept-truncated (a
// file cut after N complete records gives exactly the map of those N records
// of the intact file), and byte flips give exit 2 with one line, or exit 0
// with a valid map when the flip lands somewhere harmless.
#include <gtest/gtest.h>

#include <mrpt/io/CFileGZInputStream.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "app_runner.h"
#include "asan.h"
#include "bad_input_support.h"
#include "corruption.h"
#include "pmap/common/ply.h"
#include "pmap/input/rawlog_reader.h"
#include "pmap/mapper/planar_mapper_app.h"
#include "process_runner.h"

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

// Issue 13, item 12: hostile geometry (one odometry bit flipped, a pose
// scaled by 1e9, a cloud spread over 1e9 m) gives a clear outcome in memory
// that follows the points, not the map's extent. planar-mapper runs as a
// child process under a data limit, so a regression fails here instead of
// exhausting the machine; its peak RSS (getrusage) is the measure.
#if PMAP_TEST_ASAN
constexpr bool kSanitized = true;  // ASan reserves terabytes: no data limit
#else
constexpr bool kSanitized = false;
#endif

testing::ProcessResult runLimited(const std::vector<std::string>& args) {
  std::vector<std::string> argv;
  if (!kSanitized) {
    argv = {"/usr/bin/prlimit", "--data=4000000000"};  // 4 GB: far above the bound below
  }
  argv.push_back(testing::programPath("planar-mapper").string());
  argv.insert(argv.end(), args.begin(), args.end());
  return testing::runProcess(argv);
}

// Exit 0 with a valid map, or exit 2 / 3 with one error line and no map;
// peak RSS under 1 GiB (the bundled sample alone takes ~0.25 GiB).
// (A cloud has no poses.txt: `cloud` checks points.ply and summary.json.)
void expectClearOutcomeInBoundedMemory(const testing::ProcessResult& r, const fs::path& dir,
                                       bool cloud = false) {
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 2 || r.exit_code == 3)
      << "exit " << r.exit_code << " signal " << r.signal << ": " << r.err;
  if (r.exit_code == 0 && !cloud) {
    testing::expectValidMap(dir);
  } else if (r.exit_code == 0) {
    EXPECT_EQ(readPlyVertices(dir / "out" / "points.ply").size(),
              testing::readSummary(dir)["points"].get<std::size_t>());
  } else {
    EXPECT_EQ(r.err.rfind("planar-mapper: error: ", 0), 0u) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  }
  ::testing::Test::RecordProperty("peak_rss_kib", static_cast<int>(r.max_rss_kib));
  EXPECT_LT(static_cast<double>(r.max_rss_kib) / 1024.0, kSanitized ? 3072.0 : 1024.0);
}

// The probe's reproducer: x of one odometry reading of the bundled sample
// goes from 6.1 to 2.6e10 m (bit 1 of byte 196517 of the decompressed log).
TEST(DamagedRawlog, Item12_FlippedOdometryBitGivesAClearOutcomeInBoundedMemory) {
  const fs::path dir = testing::freshTestDir("item12_flipped_odometry");
  mrpt::io::CFileGZInputStream in(
      (fs::path(PMAP_SOURCE_DIR) / "share/sample/default-L.rawlog").string());
  testing::Bytes log;
  std::vector<char> chunk(1 << 16);
  for (std::size_t n; (n = in.Read(chunk.data(), chunk.size())) > 0;) {
    log.insert(log.end(), chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(n));
  }
  ASSERT_GT(log.size(), 196517u);
  double x = 0;
  std::memcpy(&x, &log[196510], sizeof x);
  ASSERT_NEAR(x, 6.1, 0.01) << "the sample changed: find the odometry x again";
  log[196517] = static_cast<char>(log[196517] ^ 2);
  std::memcpy(&x, &log[196510], sizeof x);
  ASSERT_GT(std::abs(x), 1e10);
  testing::writeFileBytes(dir / "flipped.rawlog", log);
  const testing::ProcessResult r =
      runLimited(testing::mapArgs(dir / "flipped.rawlog", dir, {"--no-textures"}));
  expectClearOutcomeInBoundedMemory(r, dir);
}

// A --poses file whose middle pose has x scaled by 1e9.
TEST(DamagedRawlog, Item12_APoseScaledBy1e9GivesAClearOutcomeInBoundedMemory) {
  const fs::path dir = testing::freshTestDir("item12_scaled_pose");
  testing::FixtureOptions o;
  o.cycles = 40;
  const fs::path log = testing::writeFixture(dir, o);
  ASSERT_EQ(run({"--rawlog", log.string(), "--poses-only", "-q", "--out", (dir / "true").string()}),
            0);
  std::istringstream lines(fileText(dir / "true" / "poses.txt"));
  std::ostringstream scaled;
  int pose = 0;
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty() && line[0] != '#' && ++pose == 20) {
      std::istringstream f(line);
      double t = 0, x = 0;
      f >> t >> x;
      std::string rest;
      std::getline(f, rest);
      std::ostringstream edited;
      edited.precision(17);
      edited << t << ' ' << x * 1e9 << rest;
      line = edited.str();
    }
    scaled << line << '\n';
  }
  ASSERT_GT(pose, 20);
  std::ofstream(dir / "scaled.poses.txt") << scaled.str();
  const testing::ProcessResult r = runLimited(testing::mapArgs(
      log, dir, {"--no-textures", "--poses", (dir / "scaled.poses.txt").string()}));
  expectClearOutcomeInBoundedMemory(r, dir);
}

// Three rooms (a floor on the common plane z = 0 and two walls each) 1e9 m
// apart, 8,000 points in all, mapped offline from a PLY cloud.
TEST(DamagedRawlog, Item12_ACloudSpreadOver1e9mGivesAClearOutcomeInBoundedMemory) {
  const fs::path dir = testing::freshTestDir("item12_spread_cloud");
  std::vector<double> x, y, z;
  auto add = [&](double px, double py, double pz) {
    x.push_back(px);
    y.push_back(py);
    z.push_back(pz);
  };
  for (const auto& [ox, oy] : {std::pair{0.0, 0.0}, {1e9, 0.0}, {0.0, 1e9}}) {
    for (int i = 0; i < 40; ++i) {
      for (int j = 0; j < 25; ++j) {
        const double a = 0.1 * i, b = 0.1 * j;
        add(ox + a, oy + b * 1.2, 0.0);  // floor
        add(ox, oy + a * 0.75, b);       // wall x = ox
        add(ox + a, oy, b);              // wall y = oy
      }
    }
  }
  writePlyVertices(dir / "spread.ply",
                   {{"x", "double", &x}, {"y", "double", &y}, {"z", "double", &z}});
  const testing::ProcessResult r =
      runLimited({"--cloud", (dir / "spread.ply").string(), "--no-textures", "--out",
                  (dir / "out").string(), "-q"});
  expectClearOutcomeInBoundedMemory(r, dir, true);
  if (r.exit_code == 0) {
    EXPECT_GE(testing::readSummary(dir)["surfaces"].get<int>(), 6);
  }
}

}  // namespace
}  // namespace pmap::mapper
