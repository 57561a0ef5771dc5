#include "pmap/config/strict_mrpt_config.h"

#include <gtest/gtest.h>
#include <mrpt/slam/CICP.h>
#include <mrpt/slam/CMetricMapBuilderICP.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "pmap/common/error.h"

namespace pmap::config {
namespace {

namespace fs = std::filesystem;

const fs::path kIcpSlamDir = "/usr/share/mrpt/config_files/icp-slam";
const std::vector<std::string> kOwned = {"ICP", "MappingApplication*"};

IniDocument doc(const std::string& text) {
  return IniDocument::parse(text, "t.ini");
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const ConfigError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no ConfigError";
  return {};
}

mrpt::slam::CICP::TConfigParams loadIcp(const StrictMrptConfig& cfg) {
  mrpt::slam::CICP::TConfigParams icp;
  icp.loadFromConfigFile(cfg, "ICP");
  return icp;
}

/// Runs CMetricMapBuilderICP's loader on [MappingApplication]; returns the
/// number of map initializers it created.
std::size_t loadMapping(const StrictMrptConfig& cfg) {
  mrpt::system::VerbosityLevel verbosity = mrpt::system::LVL_INFO;
  mrpt::slam::CMetricMapBuilderICP::TConfigParams params(verbosity);
  params.loadFromConfigFile(cfg, "MappingApplication");
  return params.mapInitializers.size();
}

const EffectiveConfig::Entry* entry(const EffectiveConfig& eff, const std::string& section,
                                    const std::string& key) {
  for (const auto& s : eff.sections()) {
    for (const auto& e : s.entries) {
      if (s.name == section && e.key == key) {
        return &e;
      }
    }
  }
  return nullptr;
}

/// "[section] key" of every key of owned sections that no loader read.
std::vector<std::string> unreadKeys(const IniDocument& d, const EffectiveConfig& eff) {
  std::vector<std::string> out;
  for (const auto& s : d.sectionNames()) {
    for (const auto& k : d.keys(s)) {
      const auto* e = entry(eff, s, k);
      if (e == nullptr || e->from_default) {
        out.push_back("[" + s + "] " + k);
      }
    }
  }
  return out;
}

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(StrictMrptConfig, ShippedIcpSlamConfigsKeysNotReadByTheLoaders) {
  const std::vector<std::string> expected = {
      "[ICP] onlyClosestCorrespondences",
      "[MappingApplication] rawlog_file",
      "[MappingApplication] rawlog_offset",
      "[MappingApplication] logOutput_dir",
      "[MappingApplication] LOG_FREQUENCY",
      "[MappingApplication] SAVE_3D_SCENE",
      "[MappingApplication] SAVE_POSE_LOG",
      "[MappingApplication] CAMERA_3DSCENE_FOLLOWS_ROBOT",
      "[MappingApplication] SHOW_PROGRESS_3D_REAL_TIME",
      "[MappingApplication] SHOW_PROGRESS_3D_REAL_TIME_DELAY_MS",
      "[MappingApplication] SHOW_LASER_SCANS_3D",
      "[MappingApplication] likelihoodMapSelection"};
  for (const char* name : {"icp-slam_demo_LM.ini", "icp-slam_demo_classic.ini"}) {
    const fs::path path = kIcpSlamDir / name;
    if (!fs::exists(path)) {
      GTEST_SKIP() << path << " not installed";
    }
    const auto d = IniDocument::load(path);
    EffectiveConfig eff;
    StrictMrptConfig cfg(d, kOwned, &eff);
    loadIcp(cfg);
    EXPECT_EQ(loadMapping(cfg), 1u) << name;
    EXPECT_EQ(unreadKeys(d, eff), expected) << name;
    // Issue 13, item 7: keys only MRPT's apps read are accepted and listed.
    std::vector<std::string> app_keys;
    EXPECT_NO_THROW(app_keys = cfg.checkAllRead()) << name;
    EXPECT_EQ(app_keys.size(), expected.size()) << name;
    for (const std::string& key : expected) {
      EXPECT_NE(std::find(app_keys.begin(), app_keys.end(), key), app_keys.end()) << key;
    }
  }
}

TEST(StrictMrptConfig, ShippedLmIcpSectionLoadsCleanWithoutItsObsoleteKey) {
  const fs::path path = kIcpSlamDir / "icp-slam_demo_LM.ini";
  if (!fs::exists(path)) {
    GTEST_SKIP() << path << " not installed";
  }
  std::string text = readText(path);
  const auto pos = text.find("onlyClosestCorrespondences");
  ASSERT_NE(pos, std::string::npos);
  text.erase(pos, text.find('\n', pos) - pos);  // CICP in MRPT 2.5.8 no longer reads it
  const auto d = IniDocument::parse(text, path.string());
  EffectiveConfig eff;
  StrictMrptConfig cfg(d, {"ICP"}, &eff);
  cfg.requireSection("ICP");
  const auto icp = loadIcp(cfg);
  EXPECT_NO_THROW(cfg.checkAllRead());
  EXPECT_EQ(icp.maxIterations, 80u);
  EXPECT_EQ(icp.ICP_algorithm, mrpt::slam::icpLevenbergMarquardt);
  EXPECT_FLOAT_EQ(static_cast<float>(icp.thresholdDist), 0.3f);  // MRPT reads it as a float
  EXPECT_EQ(icp.corresponding_points_decimation, 5u);
}

TEST(StrictMrptConfig, TypoInIcpKeyIsReportedWithTheNearestReadKey) {
  const auto d = doc("[ICP]\nmaxIterations = 80\nthresholdDst = 0.3\n");
  StrictMrptConfig cfg(d, kOwned);
  loadIcp(cfg);
  EXPECT_EQ(errorOf([&] { cfg.checkAllRead(); }),
            "t.ini:3: [ICP] unknown key 'thresholdDst' (did you mean 'thresholdDist'?)");

  const auto d2 = doc("[ICP]\nmaxIteration = 80\n");
  StrictMrptConfig cfg2(d2, kOwned);
  loadIcp(cfg2);
  EXPECT_EQ(errorOf([&] { cfg2.checkAllRead(); }),
            "t.ini:2: [ICP] unknown key 'maxIteration' (did you mean 'maxIterations'?)");
}

TEST(StrictMrptConfig, ValuesThatDoNotParseAsTheExpectedTypeAreReported) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"thresholdDist = abc", "t.ini:2: [ICP] thresholdDist = 'abc': not a number"},
      {"thresholdDist = 1.5m", "t.ini:2: [ICP] thresholdDist = '1.5m': not a number"},
      {"maxIterations = abc", "t.ini:2: [ICP] maxIterations = 'abc': not a number"},
      {"maxIterations = 4.5", "t.ini:2: [ICP] maxIterations = '4.5': not an integer"},
      {"maxIterations = 99999999999",
       "t.ini:2: [ICP] maxIterations = '99999999999': out of range for int"},
      {"thresholdAng_DEG = 1e300",
       "t.ini:2: [ICP] thresholdAng_DEG = '1e300': out of range for float"},
      {"ALFA = nan", "t.ini:2: [ICP] ALFA = 'nan': not a number"},
      {"doRANSAC = maybe",
       "t.ini:2: [ICP] doRANSAC = 'maybe': not a boolean or an integer (expected true/false, "
       "yes/no, on/off, 1/0 or an integer)"}};
  for (const auto& [line, message] : cases) {
    const auto d = doc("[ICP]\n" + line + "\n");
    StrictMrptConfig cfg(d, kOwned);
    const auto icp = loadIcp(cfg);  // lenient MRPT code must not see the bad text
    EXPECT_EQ(errorOf([&] { cfg.checkAllRead(); }), message);
    EXPECT_EQ(icp.maxIterations, mrpt::slam::CICP::TConfigParams().maxIterations);
  }
}

TEST(StrictMrptConfig, BoolSpellingsReachMrptAsOneOrZero) {
  // MRPT's own read_bool reads "on" as false.
  const auto d = doc("[ICP]\nonlyUniqueRobust = on\ndoRANSAC = Yes\nuse_kernel = off\n");
  StrictMrptConfig cfg(d, kOwned);
  const auto icp = loadIcp(cfg);
  EXPECT_NO_THROW(cfg.checkAllRead());
  EXPECT_TRUE(icp.onlyUniqueRobust);
  EXPECT_TRUE(icp.doRANSAC);
  EXPECT_FALSE(icp.use_kernel);
}

TEST(StrictMrptConfig, EffectiveValuesAreRecordedAndReproduceTheRun) {
  const auto d = doc("[ICP]\nmaxIterations = 80\nICP_algorithm = icpLevenbergMarquardt\n");
  EffectiveConfig eff;
  StrictMrptConfig cfg(d, kOwned, &eff);
  const auto icp = loadIcp(cfg);
  ASSERT_NE(entry(eff, "ICP", "maxIterations"), nullptr);
  EXPECT_EQ(entry(eff, "ICP", "maxIterations")->value, "80");
  EXPECT_FALSE(entry(eff, "ICP", "maxIterations")->from_default);
  EXPECT_EQ(entry(eff, "ICP", "doRANSAC")->value, "0");
  EXPECT_TRUE(entry(eff, "ICP", "doRANSAC")->from_default);
  EXPECT_EQ(entry(eff, "ICP", "covariance_varPoints")->value, "0.0004");  // a float default
  EXPECT_EQ(entry(eff, "ICP", "thresholdDist")->value, "0.75");
  EXPECT_EQ(entry(eff, "ICP", "ICP_covariance_method")->value, "");  // enum: loader's default

  const auto again = IniDocument::parse(eff.toIniText({"effective"}), "effective.ini");
  StrictMrptConfig cfg2(again, kOwned);
  const auto icp2 = loadIcp(cfg2);
  EXPECT_NO_THROW(cfg2.checkAllRead());
  EXPECT_EQ(icp2.maxIterations, icp.maxIterations);
  EXPECT_EQ(icp2.ICP_algorithm, icp.ICP_algorithm);
  EXPECT_EQ(icp2.covariance_varPoints, icp.covariance_varPoints);
  EXPECT_EQ(icp2.thresholdAng, icp.thresholdAng);
  EXPECT_EQ(icp2.kernel_rho, icp.kernel_rho);
  EXPECT_EQ(icp2.use_kernel, icp.use_kernel);
}

TEST(StrictMrptConfig, MappingApplicationSubSectionsAreChecked) {
  const std::string base = "[MappingApplication]\npointsMap_count = 1\n";
  {
    const auto d = doc(base + "[MappingApplication_pointsMap_00_insertOpts]\nisPlanarMap = 1\n");
    EffectiveConfig eff;
    StrictMrptConfig cfg(d, kOwned, &eff);
    EXPECT_EQ(loadMapping(cfg), 1u);
    EXPECT_NO_THROW(cfg.checkAllRead());
    EXPECT_NE(entry(eff, "MappingApplication_pointsMap_00_likelihoodOpts", "sigma_dist"), nullptr);
  }
  {
    const auto d = doc(base + "[MappingApplication_pointsMap_00_insertOpts]\nisPlanarMapp = 1\n");
    StrictMrptConfig cfg(d, kOwned);
    loadMapping(cfg);
    EXPECT_EQ(errorOf([&] { cfg.checkAllRead(); }),
              "t.ini:4: [MappingApplication_pointsMap_00_insertOpts] unknown key 'isPlanarMapp' "
              "(did you mean 'isPlanarMap'?)");
  }
  {
    const auto d = doc(base + "[MappingApplication_pointsMap_0_insertOpts]\nisPlanarMap = 1\n");
    StrictMrptConfig cfg(d, kOwned);
    loadMapping(cfg);
    EXPECT_EQ(errorOf([&] { cfg.checkAllRead(); }),
              "t.ini:4: [MappingApplication_pointsMap_0_insertOpts]: section not read by any MRPT "
              "loader");
  }
}

TEST(StrictMrptConfig, SuggestsKeysReadInOtherOwnedSections) {
  const auto d =
      doc("[MappingApplication]\npointsMap_count = 1\n"
          "[MappingApplication_pointsMap_00_insertOpts]\nsigma_dist = 0.1\n");
  StrictMrptConfig cfg(d, kOwned);
  loadMapping(cfg);
  EXPECT_EQ(errorOf([&] { cfg.checkAllRead(); }),
            "t.ini:4: [MappingApplication_pointsMap_00_insertOpts] unknown key 'sigma_dist' (did "
            "you mean 'sigma_dist' in [MappingApplication_pointsMap_00_likelihoodOpts]?)");
}

TEST(StrictMrptConfig, SectionsNotOwnedAreNotChecked) {
  const auto d = doc("[ICP]\nmaxIterations = 3\n[Other]\nwhatever = 1\n[icp]\nALFA = 1\n");
  StrictMrptConfig cfg(d, kOwned);
  const auto icp = loadIcp(cfg);
  EXPECT_NO_THROW(cfg.checkAllRead());
  EXPECT_EQ(icp.maxIterations, 3u);
  EXPECT_EQ(icp.ALFA, mrpt::slam::CICP::TConfigParams().ALFA);  // [icp] is not [ICP]
}

TEST(StrictMrptConfig, RequireSectionSuggestsTheNearestName) {
  const auto d = doc("[icp]\nALFA = 1\n");
  StrictMrptConfig cfg(d, kOwned);
  EXPECT_EQ(errorOf([&] { cfg.requireSection("ICP"); }),
            "t.ini: missing section [ICP] (did you mean [icp]?)");
  EXPECT_EQ(errorOf([&] { cfg.requireSection("MappingApplication"); }),
            "t.ini: missing section [MappingApplication]");
}

TEST(StrictMrptConfig, LoaderExceptionsBecomeConfigErrorsNamingTheKey) {
  const auto d = doc("[ICP]\nICP_algorithm = icpFancy\n");
  StrictMrptConfig cfg(d, kOwned);
  const std::string msg = errorOf([&] {
    try {
      loadIcp(cfg);
    } catch (const ConfigError&) {
      throw;
    } catch (const std::exception& e) {
      cfg.throwLoaderError(e);
    }
  });
  EXPECT_EQ(msg,
            "t.ini:2: [ICP] ICP_algorithm = 'icpFancy': Invalid value 'icpFancy' for enum type "
            "while reading key='ICP_algorithm'.");
}

TEST(StrictMrptConfig, MissingRequiredKeyOfALoaderIsReported) {
  // MRPT's gas-grid initializer reads gasSensorLabel with failIfNotFound =
  // true (and leaks its map definition when that throws, so it is not run
  // here under the sanitizers); this is the same call.
  const auto d = doc("[MappingApplication_gasGrid_00_insertOpts]\nsensorLabel = x\n");
  StrictMrptConfig cfg(d, kOwned);
  std::string msg;
  try {
    cfg.read_string("MappingApplication_gasGrid_00_insertOpts", "gasSensorLabel", "", true);
  } catch (const std::exception& e) {
    msg = errorOf([&] { cfg.throwLoaderError(e); });
  }
  const std::string expected =
      "t.ini: [MappingApplication_gasGrid_00_insertOpts] missing required key 'gasSensorLabel'";
  EXPECT_EQ(msg, expected);
  // Every problem at once: the missing key, then the key nobody read.
  EXPECT_EQ(errorOf([&] { cfg.checkAllRead(); }),
            expected +
                "\nt.ini:2: [MappingApplication_gasGrid_00_insertOpts] unknown key "
                "'sensorLabel' (did you mean 'gasSensorLabel'?)");
}

TEST(StrictMrptConfig, WrittenValuesAndKeyListingsAreVisibleToMrpt) {
  const auto d = doc("[ICP]\nALFA = 0.5\n");
  StrictMrptConfig cfg(d, kOwned);
  cfg.write("Extra", "n", 7);
  EXPECT_EQ(cfg.read_int("Extra", "n", 0), 7);
  std::vector<std::string> sections, keys;
  cfg.getAllSections(sections);
  EXPECT_EQ(sections, (std::vector<std::string>{"ICP", "Extra"}));
  cfg.getAllKeys("ICP", keys);
  EXPECT_EQ(keys, (std::vector<std::string>{"ALFA"}));
  EXPECT_TRUE(cfg.sectionExists("ICP"));
  EXPECT_TRUE(cfg.keyExists("ICP", "ALFA"));
  cfg.clear();
  EXPECT_EQ(cfg.read_int("Extra", "n", 0), 0);
}

}  // namespace
}  // namespace pmap::config
