// Tests of the private strict JSON reader (libs/sim/src/strict_json.h).
#include "strict_json.h"

#include <gtest/gtest.h>

#include "pmap/common/error.h"

namespace pmap::sim::detail {
namespace {

TEST(StrictJson, RangesDescribeThemselves) {
  EXPECT_EQ(positive(2.0).describe(), "(0, 2]");
  EXPECT_TRUE(positive(2.0).contains(2.0));
  EXPECT_FALSE(positive(2.0).contains(0.0));
  EXPECT_FALSE(closed(0.0, 1.0).contains(std::nan("")));
}

TEST(StrictJson, ReaderRegistersKeysAndRejectsOthers) {
  const nlohmann::json j = parseStrictJson(R"({"a": 1.5, "b": true, "c": [1, 2]})", "f.json");
  JsonReader r(j, "f.json", "root");
  EXPECT_EQ(r.number("a", 0.0, closed(0, 2)), 1.5);
  EXPECT_TRUE(r.boolean("b", false));
  EXPECT_EQ(r.number("zzz", 4.0, closed(0, 5)), 4.0);  // absent: default
  try {
    r.finish();
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("f.json: unknown key \"root.c\"", 0), 0u) << e.what();
  }
  EXPECT_EQ(r.point2("c"), Eigen::Vector2d(1, 2));
  EXPECT_NO_THROW(r.finish());
}

TEST(StrictJson, TypeAndRangeErrors) {
  const nlohmann::json j = parseStrictJson(R"({"n": "x", "i": 2.5, "big": 7})", "f.json");
  JsonReader r(j, "f.json", "");
  EXPECT_THROW(r.number("n", 0.0, closed(0, 1)), ConfigError);
  EXPECT_THROW(r.integer("i", 0, 0, 10), ConfigError);
  EXPECT_THROW(r.integer("big", 0, 0, 5), ConfigError);
  EXPECT_THROW(r.requiredNumber("missing", closed(0, 1)), ConfigError);
  EXPECT_THROW(r.point3("n"), ConfigError);
}

TEST(StrictJson, IntervalsAndQuintuples) {
  const nlohmann::json j = parseStrictJson(
      R"({"ok": [0.5, 1.5], "rev": [2, 1], "out": [0, 20], "q": [1, 2, 3, 4, 5], "q4": [1, 2, 3, 4]})",
      "f.json");
  JsonReader r(j, "f.json", "cam");
  EXPECT_EQ(r.interval("ok", {0, 0}, closed(0, 10)), (std::array<double, 2>{0.5, 1.5}));
  EXPECT_EQ(r.interval("absent", {3, 4}, closed(0, 10)), (std::array<double, 2>{3, 4}));
  EXPECT_EQ(r.quintuple("q", {}, closed(0, 10))[4], 5.0);
  auto message = [&](auto&& read) {
    try {
      read();
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message([&] {
              r.interval("rev", {0, 0}, closed(0, 10));
            }).find("cam.rev: [2, 1]: the lower bound exceeds the upper bound"),
            std::string::npos);
  EXPECT_NE(message([&] {
              r.interval("out", {0, 0}, closed(0, 10));
            }).find("cam.out: 20 is out of range [0, 10]"),
            std::string::npos);
  EXPECT_NE(message([&] {
              r.quintuple("q", {}, closed(0, 4));
            }).find("cam.q: element 4: 5 is out of range [0, 4]"),
            std::string::npos);
  EXPECT_NE(message([&] {
              r.quintuple("q4", {}, closed(0, 10));
            }).find("cam.q4: expected an array of 5 numbers"),
            std::string::npos);
}

}  // namespace
}  // namespace pmap::sim::detail
