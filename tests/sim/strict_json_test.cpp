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

}  // namespace
}  // namespace pmap::sim::detail
