#include "pmap/config/section_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "pmap/common/error.h"

namespace pmap::config {
namespace {

IniDocument doc(const std::string& text) {
  return IniDocument::parse(text, "cfg.ini");
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

// The error of reading `key` alone: a value that does not parse is reported
// by finish(), first, before the keys this reader did not ask for.
template <class T>
std::string readError(const IniDocument& d, const std::string& key, T value) {
  SectionReader r(d, "S");
  r.read(key, value);
  const std::string all = errorOf([&] { r.finish(); });
  return all.substr(0, all.find('\n'));
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

TEST(SectionReader, ReadsTypedValuesAndKeepsDefaultsOfAbsentKeys) {
  const auto d =
      doc("[S]\nx = 1.5\nn = -7\nbig = 9000000000\nflag = Yes\nname = a b\nlist = a, b ,c\n"
          "empty_list =\n");
  EffectiveConfig eff;
  SectionReader r(d, "S", &eff);
  EXPECT_TRUE(r.present());
  EXPECT_EQ(r.section(), "S");
  double x = 0, y = 2.5;
  int n = 0, m = 3;
  std::int64_t big = 0;
  bool flag = false, other = true;
  std::string name, absent = "keep";
  std::vector<std::string> list, empty_list, absent_list = {"p", "q"};
  r.read("x", x);
  r.read("y", y);
  r.read("n", n);
  r.read("m", m);
  r.read("big", big);
  r.read("flag", flag);
  r.read("other", other);
  r.read("name", name);
  r.read("absent", absent);
  r.read("list", list);
  r.read("empty_list", empty_list);
  r.read("absent_list", absent_list);
  EXPECT_NO_THROW(r.finish());
  EXPECT_EQ(x, 1.5);
  EXPECT_EQ(y, 2.5);
  EXPECT_EQ(n, -7);
  EXPECT_EQ(m, 3);
  EXPECT_EQ(big, 9000000000LL);
  EXPECT_TRUE(flag);
  EXPECT_TRUE(other);
  EXPECT_EQ(name, "a b");
  EXPECT_EQ(absent, "keep");
  EXPECT_EQ(list, (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_EQ(empty_list, (std::vector<std::string>{""}));
  EXPECT_EQ(absent_list, (std::vector<std::string>{"p", "q"}));
}

TEST(SectionReader, RecordsEffectiveValuesFromFileAndDefaults) {
  const auto d = doc("[S]\nx = 1.50\n");
  EffectiveConfig eff;
  SectionReader r(d, "S", &eff);
  double x = 0, y = 0.1;
  bool b = false;
  int i = -4;
  std::vector<std::string> l = {"a", "b"};
  r.read("x", x);
  r.read("y", y);
  r.read("b", b);
  r.read("i", i);
  r.read("l", l);
  const auto* ex = entry(eff, "S", "x");
  ASSERT_NE(ex, nullptr);
  EXPECT_EQ(ex->value, "1.50");
  EXPECT_FALSE(ex->from_default);
  EXPECT_EQ(entry(eff, "S", "y")->value, "0.1");
  EXPECT_TRUE(entry(eff, "S", "y")->from_default);
  EXPECT_EQ(entry(eff, "S", "b")->value, "false");
  EXPECT_EQ(entry(eff, "S", "i")->value, "-4");
  EXPECT_EQ(entry(eff, "S", "l")->value, "a,b");
}

TEST(SectionReader, DefaultDoublesRoundTripThroughTheEffectiveIni) {
  const std::vector<double> defaults = {0.1,
                                        1.0 / 3.0,
                                        1e-300,
                                        -2.5e17,
                                        2.2250738585072014e-308,
                                        1.0e300,
                                        0.0,
                                        -0.0,
                                        123456789.123456789,
                                        std::numeric_limits<double>::max()};
  EffectiveConfig eff;
  const auto empty = doc("[S]\n");
  SectionReader writer(empty, "S", &eff);
  for (std::size_t i = 0; i < defaults.size(); ++i) {
    double v = defaults[i];
    writer.read("d" + std::to_string(i), v);
  }
  const auto back = IniDocument::parse(eff.toIniText(), "effective.ini");
  SectionReader reader(back, "S");
  for (std::size_t i = 0; i < defaults.size(); ++i) {
    double v = std::nan("");
    reader.read("d" + std::to_string(i), v);
    EXPECT_EQ(v, defaults[i]) << i << ": " << back.find("S", "d" + std::to_string(i))->value;
    EXPECT_EQ(std::signbit(v), std::signbit(defaults[i])) << i;
  }
  reader.finish();
}

TEST(SectionReader, UnparsableNumbersNameFileLineSectionAndKey) {
  const auto d =
      doc("[S]\nx = abc\nn = 4.5\nm = 99999999999\nbig = 1e3\nh = 99999999999999999999\n");
  double x = 0;
  int n = 0;
  std::int64_t big = 0;
  EXPECT_EQ(readError(d, "x", x), "cfg.ini:2: [S] x = 'abc': not a number");
  EXPECT_EQ(readError(d, "n", n), "cfg.ini:3: [S] n = '4.5': not an integer");
  EXPECT_EQ(readError(d, "m", n), "cfg.ini:4: [S] m = '99999999999': out of range for int");
  EXPECT_EQ(readError(d, "big", big), "cfg.ini:5: [S] big = '1e3': not an integer");
  EXPECT_EQ(readError(d, "h", big),
            "cfg.ini:6: [S] h = '99999999999999999999': out of range for a 64-bit integer");
}

TEST(SectionReader, NanInfAndUnitsAreNotNumbers) {
  const auto d = doc("[S]\na = nan\nb = inf\nc = 1.5m\nd =\n");
  double v = 0;
  for (const std::string key : {"a", "b", "c", "d"}) {
    EXPECT_NE(readError(d, key, v).find(": not a number"), std::string::npos) << key;
  }
}

TEST(SectionReader, BoolAcceptsTheUsualSpellingsOnly) {
  const auto d = doc("[S]\na = on\nb = OFF\nc = 1\nd = no\ne = maybe\n");
  SectionReader r(d, "S");
  bool a = false, b = true, c = false, dd = true, e = false;
  r.read("a", a);
  r.read("b", b);
  r.read("c", c);
  r.read("d", dd);
  EXPECT_TRUE(a);
  EXPECT_FALSE(b);
  EXPECT_TRUE(c);
  EXPECT_FALSE(dd);
  EXPECT_EQ(readError(d, "e", e),
            "cfg.ini:6: [S] e = 'maybe': not a boolean (expected true/false, yes/no, on/off or "
            "1/0)");
}

TEST(SectionReader, Item7_FinishReportsEveryProblemOfTheSectionAtOnce) {
  const auto d = doc("[S]\nx = abc\nsigam_m = 2\nb = maybe\n");
  SectionReader r(d, "S");
  double x = 1.5, sigma = 0;
  bool b = true;
  r.read("x", x);
  r.read("sigma_m", sigma);
  r.read("b", b);
  EXPECT_EQ(x, 1.5);  // the default stays until finish() reports
  EXPECT_EQ(errorOf([&] { r.finish(); }),
            "cfg.ini:2: [S] x = 'abc': not a number\n"
            "cfg.ini:4: [S] b = 'maybe': not a boolean (expected true/false, yes/no, on/off or "
            "1/0)\n"
            "cfg.ini:3: [S] unknown key 'sigam_m' (did you mean 'sigma_m'?)");
}

TEST(SectionReader, FinishReportsUnknownKeysWithTheNearestKnownOne) {
  const auto d = doc("[PlanarEM]\nsigma_m = 1\nsigam_m = 2\n");
  SectionReader r(d, "PlanarEM");
  double sigma = 0;
  r.read("sigma_m", sigma);
  EXPECT_EQ(errorOf([&] { r.finish(); }),
            "cfg.ini:3: [PlanarEM] unknown key 'sigam_m' (did you mean 'sigma_m'?)");

  const auto d2 = doc("[PlanarEM]\ncompletely_different = 1\n");
  SectionReader r2(d2, "PlanarEM");
  r2.read("sigma_m", sigma);
  EXPECT_EQ(errorOf([&] { r2.finish(); }),
            "cfg.ini:2: [PlanarEM] unknown key 'completely_different'");
}

TEST(SectionReader, KeysAreCaseSensitiveButTheSuggestionIsNot) {
  const auto d = doc("[S]\nSigma_M = 1\n");
  SectionReader r(d, "S");
  double sigma = 7;
  r.read("sigma_m", sigma);
  EXPECT_EQ(sigma, 7);
  EXPECT_EQ(errorOf([&] { r.finish(); }),
            "cfg.ini:2: [S] unknown key 'Sigma_M' (did you mean 'sigma_m'?)");
}

TEST(SectionReader, MissingSections) {
  const auto d = doc("[sensors]\nlabel = x\n[Other]\n");
  EXPECT_EQ(errorOf([&] { SectionReader r(d, "Sensors"); }),
            "cfg.ini: missing section [Sensors] (did you mean [sensors]?)");
  EXPECT_EQ(errorOf([&] { SectionReader r(d, "PlanarEM"); }),
            "cfg.ini: missing section [PlanarEM]");

  EffectiveConfig eff;
  SectionReader r(d, "PlanarEM", &eff, Presence::kOptional);
  EXPECT_FALSE(r.present());
  double sigma = 0.25;
  r.read("sigma_m", sigma);
  EXPECT_EQ(sigma, 0.25);
  EXPECT_NO_THROW(r.finish());
  ASSERT_NE(entry(eff, "PlanarEM", "sigma_m"), nullptr);
  EXPECT_EQ(entry(eff, "PlanarEM", "sigma_m")->value, "0.25");
}

TEST(SectionReader, FailNamesTheValueOrTheDefault) {
  const auto d = doc("[S]\nsigma_m = -1\n");
  SectionReader r(d, "S");
  double sigma = 0, range = 80;
  r.read("sigma_m", sigma);
  r.read("max_range_m", range);
  EXPECT_EQ(errorOf([&] { r.fail("sigma_m", "must be > 0"); }),
            "cfg.ini:2: [S] sigma_m = -1: must be > 0");
  EXPECT_EQ(errorOf([&] { r.fail("max_range_m", "must be < 50"); }),
            "cfg.ini: [S] max_range_m = 80 (default): must be < 50");
  EXPECT_EQ(errorOf([&] { r.fail("never_read", "rule"); }),
            "cfg.ini: [S] never_read (default): rule");
}

struct DemoOptions {
  double sigma_m = 0.05;
  int max_iterations = 40;
  void load(SectionReader& r) {
    r.read("sigma_m", sigma_m);
    r.read("max_iterations", max_iterations);
  }
  bool validate(std::string* why) const {
    if (!(sigma_m > 0)) {
      *why = "sigma_m must be > 0";
      return false;
    }
    return true;
  }
};

TEST(SectionReader, LoadOptionsReadsFinishesAndValidates) {
  EffectiveConfig eff;
  DemoOptions opts;
  loadOptions(doc("[PlanarEM]\nsigma_m = 0.1\n"), "PlanarEM", opts, &eff);
  EXPECT_EQ(opts.sigma_m, 0.1);
  EXPECT_EQ(opts.max_iterations, 40);
  EXPECT_EQ(eff.sections().at(0).entries.size(), 2u);

  DemoOptions bad;
  EXPECT_EQ(
      errorOf([&] { loadOptions(doc("[PlanarEM]\nsigma_m = 0\n"), "PlanarEM", bad, nullptr); }),
      "cfg.ini: [PlanarEM] sigma_m must be > 0");
  EXPECT_EQ(errorOf([&] {
              loadOptions(doc("[PlanarEM]\nmax_iteration = 3\n"), "PlanarEM", bad, nullptr);
            }),
            "cfg.ini:2: [PlanarEM] unknown key 'max_iteration' (did you mean 'max_iterations'?)");
  DemoOptions absent;
  EXPECT_NO_THROW(loadOptions(doc(""), "PlanarEM", absent, nullptr, Presence::kOptional));
}

}  // namespace
}  // namespace pmap::config
