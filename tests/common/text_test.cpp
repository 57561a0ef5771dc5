#include "pmap/common/text.h"

#include <gtest/gtest.h>

namespace pmap {
namespace {

TEST(Text, TrimRemovesSpacesTabsAndLineEnds) {
  EXPECT_EQ(trim("  a b \t\r\n"), "a b");
  EXPECT_EQ(trim(""), "");
  EXPECT_EQ(trim(" \t "), "");
}

TEST(Text, ParseDoubleIsStrict) {
  EXPECT_DOUBLE_EQ(*parseDouble(" 1.5 "), 1.5);
  EXPECT_DOUBLE_EQ(*parseDouble("-2e-3"), -2e-3);
  EXPECT_FALSE(parseDouble("1.5m"));
  EXPECT_FALSE(parseDouble("abc"));
  EXPECT_FALSE(parseDouble(""));
  EXPECT_FALSE(parseDouble("nan"));
  EXPECT_FALSE(parseDouble("inf"));
  EXPECT_FALSE(parseDouble("1e999"));
}

TEST(Text, ParseIntIsStrict) {
  EXPECT_EQ(*parseInt("42"), 42);
  EXPECT_EQ(*parseInt("-7"), -7);
  EXPECT_FALSE(parseInt("4.2"));
  EXPECT_FALSE(parseInt("99999999999999999999"));
  EXPECT_FALSE(parseInt("12abc"));
}

TEST(Text, ParseBoolAcceptsTheUsualSpellingsOnly) {
  EXPECT_TRUE(*parseBool("Yes"));
  EXPECT_TRUE(*parseBool("1"));
  EXPECT_FALSE(*parseBool("off"));
  EXPECT_FALSE(parseBool("maybe"));
}

TEST(Text, NearestWordSuggestsPlausibleTypos) {
  const std::vector<std::string> keys = {"sigma_m", "z_max_m", "kappa"};
  EXPECT_EQ(nearestWord("sigam_m", keys), "sigma_m");
  EXPECT_EQ(nearestWord("KAPPA", keys), "kappa");
  EXPECT_EQ(nearestWord("completely_different", keys), "");
}

TEST(Text, SplitFieldsDropsEmptyFields) {
  const auto f = splitFields("  1 2\t\t3 ");
  ASSERT_EQ(f.size(), 3u);
  EXPECT_EQ(f[2], "3");
}

TEST(EscapeHtml, EscapesMarkup) {
  EXPECT_EQ(escapeHtml("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
  EXPECT_EQ(escapeHtml(""), "");
}

}  // namespace
}  // namespace pmap
