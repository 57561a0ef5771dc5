// Issue 13: what a new user met, item by item (labels, the bundled sample,
// progress, timings, poses.tum, MRPT ini reuse, "not a rawlog", docs,
// implausible motion). Each test is named after its item.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "app_runner.h"
#include "pmap/mapper/planar_mapper_app.h"
#include "process_runner.h"
#include "rawlog_fixtures.h"
#include "test_files.h"

namespace pmap::mapper {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kSource = PMAP_SOURCE_DIR;
const fs::path kDefaultIni = kSource / "config/default.ini";
const fs::path kSample = kSource / "share/sample/default-L.rawlog";
const fs::path kMrptData = "/usr/share/mrpt/datasets";

struct Outcome {
  int code;
  std::string err;
  std::string out;
};

// planar-mapper in-process, its stderr and stdout captured.
Outcome mapper(const std::vector<std::string>& args) {
  ::testing::internal::CaptureStderr();
  ::testing::internal::CaptureStdout();
  const int code = testing::runMain(&planarMapperMain, "planar-mapper", args);
  Outcome r{code, ::testing::internal::GetCapturedStderr(), ""};
  r.out = ::testing::internal::GetCapturedStdout();
  return r;
}

fs::path fixture(const fs::path& dir, int cycles = 12) {
  testing::FixtureOptions o;
  o.cycles = cycles;
  testing::writeFixtureRawlog(dir / "log.rawlog", o);
  return dir / "log.rawlog";
}

json readJson(const fs::path& p) {
  std::ifstream in(p);
  return json::parse(in);
}

int countOf(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
    ++n;
  }
  return n;
}

TEST(UserItems, Item2_WrongPoseLaserLabelIsAnErrorListingTheLabels) {
  const fs::path dir = testing::freshTestDir("item2_label");
  const fs::path log = fixture(dir);
  const Outcome r = mapper(
      {"--config",
       testing::editedDefaultIni(dir, "pose_laser = LASER_H", "pose_laser = LASER_HORIZ").string(),
       "--rawlog", log.string(), "--out", (dir / "out").string(), "-q"});
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("[Sensors] pose_laser = LASER_HORIZ"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("'LASER_H' (CObservation2DRangeScan) x 12"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("'LASER_V' (CObservation2DRangeScan) x 12"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out/summary.json"));
}

TEST(UserItems, Item2_AbsentMemberOfARoleWarns) {
  const fs::path dir = testing::freshTestDir("item2_member");
  const fs::path log = fixture(dir);
  const Outcome r =
      mapper({"--config",
              testing::editedDefaultIni(dir, "structure  = LASER_V", "structure = LASER_V, OPENNI2")
                  .string(),
              "--rawlog", log.string(), "--out", (dir / "out").string(), "-q", "--no-textures"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(countOf(r.err, "warning: [Sensors] structure: no observation labelled 'OPENNI2'"), 1)
      << r.err;
  const json s = readJson(dir / "out/summary.json");
  EXPECT_EQ(s["warnings"].size(), 1u) << s["warnings"];
}

TEST(UserItems, Item2_WrongKeepLabelIsAnError) {
  const fs::path dir = testing::freshTestDir("item2_keep");
  const Outcome r = mapper({"--rawlog", fixture(dir).string(), "--keep-label", "LASER_X", "--out",
                            (dir / "out").string(), "-q"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("--keep-label = LASER_X"), std::string::npos) << r.err;
}

TEST(UserItems, Item2_ListLabelsPrintsTheFileLabels) {
  const fs::path dir = testing::freshTestDir("item2_list");
  const Outcome r = mapper({"--rawlog", fixture(dir).string(), "--list-labels"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("36 records"), std::string::npos) << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex("CObservationOdometry +ODOMETRY +12 "))) << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex("CObservation2DRangeScan +LASER_V +12")))
      << r.out;
}

TEST(UserItems, Item3_ConfigWithoutInputIsAUsageError) {
  const fs::path dir = testing::freshTestDir("item3_config");
  const Outcome r = mapper({"--config", kDefaultIni.string(), "--out", (dir / "out").string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("needs an input: give --rawlog FILE or --cloud FILE.ply"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(UserItems, Item3_NoInputMapsTheBundledSampleAndSaysSo) {
  const fs::path dir = testing::freshTestDir("item3_sample");
  const Outcome r = mapper({"--out", (dir / "out").string(), "--mode", "raw", "--to-index", "40"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("no --rawlog given: mapping the bundled sample"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("default-L.rawlog"), std::string::npos) << r.err;
}

// Stages longer than a second report progress when stderr is a file: at
// least their "done" line, and a line every few seconds while they run.
TEST(UserItems, Item4_ProgressLinesForLongStagesWhenNotATerminal) {
  const fs::path dir = testing::freshTestDir("item4_progress");
  const testing::ProcessResult p =
      testing::runProcess({testing::programPath("planar-mapper").string(), "--rawlog",
                           kSample.string(), "--mode", "offline", "--out", (dir / "out").string()});
  ASSERT_EQ(p.exit_code, 0) << p.err;
  const json t = readJson(dir / "out/summary.json")["timing_s"];
  const struct {
    const char* key;
    const char* label;
  } stages[] = {{"em", "planar-mapper: EM"},
                {"refine", "planar-mapper: refinement"},
                {"texture", "planar-mapper: textures"},
                {"write", "planar-mapper: writing"}};
  int checked = 0;
  for (const auto& s : stages) {
    // A stage's clock includes a little set-up before its progress line
    // starts: 1.5 s of stage time is over a second of progress time.
    if (t[s.key].get<double>() >= 1.5) {
      ++checked;
      EXPECT_NE(p.err.find(std::string(s.label) + ": done in"), std::string::npos) << s.key << "\n"
                                                                                   << p.err;
    }
    if (t[s.key].get<double>() >= 5.0) {  // a running line before the done line
      EXPECT_TRUE(
          std::regex_search(p.err, std::regex(std::string(s.label) + ": [0-9/ ()%]*[0-9.]+ s")))
          << s.key << "\n"
          << p.err;
    }
  }
  EXPECT_GE(checked, 1) << "no stage took 1.5 s: nothing checked\n" << t;
  EXPECT_NE(p.err.find("planar-mapper: reading: done in"), std::string::npos) << p.err;
}

void expectTimesAddUp(const json& t) {
  double sum = 0;
  for (const auto& [key, value] : t.items()) {
    if (key != "total") {
      EXPECT_GE(value.get<double>(), 0.0) << key;
      sum += value.get<double>();
    }
  }
  for (const char* key : {"read", "pose", "map", "em", "refine", "texture", "write", "other"}) {
    EXPECT_TRUE(t.contains(key)) << key;
  }
  EXPECT_NEAR(sum, t["total"].get<double>(), 1e-9 * std::max(1.0, sum)) << t;
}

TEST(UserItems, Item5_SummaryTimesAddUp) {
  const fs::path dir = testing::freshTestDir("item5_times");
  ASSERT_EQ(mapper({"--rawlog", fixture(dir).string(), "--out", (dir / "out").string(), "-q"}).code,
            0);
  expectTimesAddUp(readJson(dir / "out/summary.json")["timing_s"]);
}

// tests_rgbd.rawlog (one Kinect frame): no negative stage, no realtime factor
// for a recording without duration, and report.html lists every stage.
TEST(UserItems, Item5_KinectFrameTimesAreNotNegative) {
  const fs::path dir = testing::freshTestDir("item5_rgbd");
  const Outcome r =
      mapper({"--config", (kSource / "config/mrpt-rgbd.ini").string(), "--rawlog",
              (kMrptData / "tests_rgbd.rawlog").string(), "--out", (dir / "out").string(), "-q"});
  ASSERT_EQ(r.code, 0) << r.err;
  const json s = readJson(dir / "out/summary.json");
  expectTimesAddUp(s["timing_s"]);
  EXPECT_TRUE(s["realtime_factor"].is_null()) << s["realtime_factor"];
  std::ifstream in(dir / "out/report/report.html");
  const std::string html((std::istreambuf_iterator<char>(in)), {});
  for (const char* row : {"time: refinement", "time: textures", "time: other"}) {
    EXPECT_NE(html.find(row), std::string::npos) << row;
  }
}

TEST(UserItems, Item6_PosesOnlyWritesTumAndSaysWhatItFound) {
  const fs::path dir = testing::freshTestDir("item6_poses");
  const Outcome r =
      mapper({"--rawlog", fixture(dir).string(), "--poses-only", "--out", (dir / "out").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(std::regex_search(
      r.err, std::regex("planar-mapper: [0-9]+ poses \\(icp\\), path [0-9.]+ m, final pose x "
                        "[-0-9.]+ m, y [-0-9.]+ m, yaw [-0-9.]+ deg")))
      << r.err;
  EXPECT_EQ(r.err.find("0 scans, 0 points"), std::string::npos) << r.err;
  std::ifstream txt(dir / "out/poses.txt"), tum(dir / "out/poses.tum");
  std::string a, b;
  int rows = 0;
  while (std::getline(txt, a) && std::getline(tum, b)) {
    if (a[0] == '#') {
      continue;
    }
    std::istringstream fa(a), fb(b);
    double ta, tb, xa, xb;
    fa >> ta >> xa;
    fb >> tb >> xb;
    EXPECT_DOUBLE_EQ(ta, tb);
    EXPECT_DOUBLE_EQ(xa, xb);
    ++rows;
  }
  EXPECT_GT(rows, 10);
}

// An icp-slam ini is reused as it is: @included below the project's
// [Sensors] (the only section a log's labels need); its app-only keys are
// accepted with one warning.
TEST(UserItems, Item7_IcpSlamIniIsReusable) {
  const fs::path dir = testing::freshTestDir("item7_icp_slam");
  const fs::path icp_slam = "/usr/share/mrpt/config_files/icp-slam/icp-slam_demo_LM.ini";
  std::ofstream(dir / "my.ini") << "[Sensors]\npose_laser = LASER_H\nodometry = ODOMETRY\n"
                                   "structure = none\ncameras = none\n@include "
                                << icp_slam.string() << "\n";
  const Outcome r =
      mapper({"--config", (dir / "my.ini").string(), "--rawlog", fixture(dir).string(),
              "--poses-only", "--out", (dir / "out").string(), "-q"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(countOf(r.err, "warning:"), 1) << r.err;
  for (const char* key : {"rawlog_file", "logOutput_dir", "SHOW_PROGRESS_3D_REAL_TIME",
                          "onlyClosestCorrespondences"}) {
    EXPECT_NE(r.err.find(key), std::string::npos) << key << "\n" << r.err;
  }
}

TEST(UserItems, Item7_AllConfigErrorsOfAFileInOneRun) {
  const fs::path dir = testing::freshTestDir("item7_errors");
  const fs::path ini = testing::editedDefaultIni(dir, "kappa = 200", "kappa = abc\nsigam_m = 0.02");
  std::ifstream in(ini);
  std::string text((std::istreambuf_iterator<char>(in)), {});
  in.close();
  text.replace(text.find("raw_map = true"), 14, "raw_map = maybe");
  text += "\n[Bogus]\nx = 1\n";
  std::ofstream(ini) << text;
  const Outcome r = mapper({"--config", ini.string(), "--rawlog", fixture(dir).string(), "--out",
                            (dir / "out").string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("unknown section [Bogus]"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("kappa = 'abc'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("unknown key 'sigam_m' (did you mean 'sigma_m'?)"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("raw_map = 'maybe'"), std::string::npos) << r.err;
  EXPECT_EQ(countOf(r.err, "planar-mapper: error: "), 4) << r.err;
}

TEST(UserItems, Item7_ProjectSectionsMayBeLeftOutButUnknownKeysStayErrors) {
  const fs::path dir = testing::freshTestDir("item7_sections");
  fs::copy_file(kSource / "config/icp.ini", dir / "icp.ini");
  std::ofstream(dir / "min.ini") << "[Sensors]\ncameras = none\n@include icp.ini\n";
  EXPECT_EQ(mapper({"--config", (dir / "min.ini").string(), "--rawlog", fixture(dir).string(),
                    "--out", (dir / "out").string(), "-q"})
                .code,
            0);
  std::ofstream(dir / "typo.ini") << "[Sensors]\ncameras = none\n[Output]\nrawmap = true\n"
                                     "@include icp.ini\n";
  const Outcome r = mapper({"--config", (dir / "typo.ini").string(), "--rawlog",
                            (dir / "log.rawlog").string(), "--out", (dir / "out2").string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("did you mean 'raw_map'?"), std::string::npos) << r.err;
}

TEST(UserItems, Item8_JsonGivenAsTheRawlogIsNotARawlog) {
  const fs::path dir = testing::freshTestDir("item8_json");
  std::ofstream(dir / "run.gt.json") << "{\n  \"surfaces\": []\n}\n";
  const Outcome r =
      mapper({"--rawlog", (dir / "run.gt.json").string(), "--out", (dir / "out").string()});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("not a rawlog"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("CStream"), std::string::npos) << r.err;
}

TEST(UserItems, Item8_SnapshotEveryWithOfflineIsAUsageError) {
  const fs::path dir = testing::freshTestDir("item8_snapshot");
  const Outcome r = mapper({"--rawlog", fixture(dir).string(), "--mode", "offline",
                            "--snapshot-every", "5", "--out", (dir / "out").string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("--snapshot-every"), std::string::npos) << r.err;
}

// Every `--config X` and `--rawlog X` a doc or the README shows names a file
// the project has (doc/usage.md once said `--config sena.ini`).
TEST(UserItems, Item9_DocsNameFilesThatExist) {
  std::vector<fs::path> docs = {kSource / "README.md"};
  for (const auto& e : fs::directory_iterator(kSource / "doc")) {
    if (e.path().extension() == ".md") {
      docs.push_back(e.path());
    }
  }
  const std::regex config_arg("--config (config/[A-Za-z0-9_./-]+\\.ini)");
  int seen = 0;
  for (const fs::path& doc : docs) {
    std::ifstream in(doc);
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    for (std::sregex_iterator m(text.begin(), text.end(), config_arg), end; m != end; ++m) {
      ++seen;
      EXPECT_TRUE(fs::exists(kSource / (*m)[1].str())) << doc.filename() << ": " << (*m)[0];
    }
    EXPECT_EQ(text.find("--config sena.ini"), std::string::npos) << doc;
  }
  EXPECT_GE(seen, 1);
}

// The bundled sample with one flipped bit in one odometry reading (x from
// 6.1 m to 2.6e10 m): the reading is dropped and counted, the run stays small.
TEST(UserItems, Item12_FlippedOdometryBitIsDroppedWithBoundedMemory) {
  const fs::path dir = testing::freshTestDir("item12_flip");
  const testing::ProcessResult unzip = testing::runProcess(
      {"/bin/sh", "-c", "zcat '" + kSample.string() + "' > '" + (dir / "p.rawlog").string() + "'"});
  ASSERT_EQ(unzip.exit_code, 0);
  std::fstream f(dir / "p.rawlog", std::ios::in | std::ios::out | std::ios::binary);
  f.seekg(196517);
  char byte = 0;
  f.read(&byte, 1);
  byte = static_cast<char>(byte ^ 2);
  f.seekp(196517);
  f.write(&byte, 1);
  f.close();
  const testing::ProcessResult p =
      testing::runProcess({testing::programPath("planar-mapper").string(), "-q", "--no-textures",
                           "--rawlog", (dir / "p.rawlog").string(), "--out", (dir / "m").string()});
  ASSERT_EQ(p.exit_code, 0) << p.err;
  EXPECT_LT(p.max_rss_kib, 1024 * 1024) << "peak RSS " << p.max_rss_kib << " KiB";
  EXPECT_EQ(countOf(p.err, "warning: "), 1) << p.err;
  EXPECT_NE(p.err.find("implausible motion: 1 odometry"), std::string::npos) << p.err;
  const json s = readJson(dir / "m/summary.json");
  EXPECT_EQ(s["poses"]["implausible_dropped"], 1);
  EXPECT_EQ(s["warnings"].size(), 1u);
  std::ifstream poses(dir / "m/poses.txt");
  std::string line;
  while (std::getline(poses, line)) {
    double t, x, y;
    if (line[0] != '#' && std::istringstream(line) >> t >> x >> y) {
      EXPECT_LT(std::hypot(x, y), 100.0) << line;
    }
  }
}

// A --poses file in which one pose's x is multiplied by 1e9.
TEST(UserItems, Item12_GivenPoseScaledBy1e9IsDropped) {
  const fs::path dir = testing::freshTestDir("item12_poses");
  std::ifstream in(kSource / "share/sample/default-L.poses.txt");
  std::ofstream out(dir / "p.txt");
  std::string line;
  int k = 0;
  while (std::getline(in, line)) {
    if (line[0] != '#' && ++k == 100) {
      std::istringstream fields(line);
      std::string t;
      double x;
      fields >> t >> x;
      std::string rest;
      std::getline(fields, rest);
      line = t + " " + std::to_string(x * 1e9) + rest;
    }
    out << line << "\n";
  }
  out.close();
  const testing::ProcessResult p = testing::runProcess(
      {testing::programPath("planar-mapper").string(), "-q", "--no-textures", "--rawlog",
       kSample.string(), "--poses", (dir / "p.txt").string(), "--out", (dir / "m").string()});
  ASSERT_EQ(p.exit_code, 0) << p.err;
  EXPECT_LT(p.max_rss_kib, 1024 * 1024) << "peak RSS " << p.max_rss_kib << " KiB";
  EXPECT_NE(p.err.find("implausible motion: 1 given poses dropped"), std::string::npos) << p.err;
  EXPECT_EQ(readJson(dir / "m/summary.json")["poses"]["implausible_dropped"], 1);
}

// MRPT's demo logs whose first action has a zero timestamp: MRPT's ICP
// asserted on it (exit 2). The action takes its sensory frame's time.
TEST(UserItems, Item12_ZeroTimestampActionsTakeTheirFrameTime) {
  const fs::path dir = testing::freshTestDir("item12_zero_time");
  std::ofstream(dir / "demo.ini") << "[Sensors]\npose_laser =\nodometry =\nstructure = none\n"
                                     "cameras = none\n@include "
                                  << (kSource / "config/icp.ini").string() << "\n";
  const Outcome r = mapper({"--config", (dir / "demo.ini").string(), "--rawlog",
                            (kMrptData / "localization_demo.rawlog").string(), "--poses-only",
                            "--out", (dir / "out").string(), "-q"});
  ASSERT_EQ(r.code, 0) << r.err;
  const json s = readJson(dir / "out/summary.json");
  EXPECT_EQ(s["poses"]["actions_timed_by_frame"], 1);
  EXPECT_EQ(s["poses"]["count"], 37);
  // kf-slam_demo.rawlog has no laser at all (bearing-range observations):
  // a clear configuration error, not an assert from the ICP stage.
  const Outcome kf = mapper({"--config", (dir / "demo.ini").string(), "--rawlog",
                             (kMrptData / "kf-slam_demo.rawlog").string(), "--poses-only", "--out",
                             (dir / "kf").string(), "-q"});
  EXPECT_EQ(kf.code, 1) << kf.err;
  EXPECT_NE(kf.err.find("CObservationBearingRange"), std::string::npos) << kf.err;
}

}  // namespace
}  // namespace pmap::mapper
