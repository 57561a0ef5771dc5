#include "pmap/config/effective_config.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pmap/config/ini_document.h"

namespace pmap::config {
namespace {

TEST(EffectiveConfig, EmptyConfigWritesOnlyTheHeader) {
  const EffectiveConfig eff;
  EXPECT_TRUE(eff.sections().empty());
  EXPECT_EQ(eff.toIniText(), "");
  EXPECT_EQ(eff.toIniText({"run 1", "", "two\nlines"}), "# run 1\n#\n# two\n# lines\n");
}

TEST(EffectiveConfig, KeepsFirstRecordedOrderAndReplacesInPlace) {
  EffectiveConfig eff;
  eff.record("B", "x", "1", true);
  eff.record("A", "y", "2", false);
  eff.record("B", "z", "3", false);
  eff.record("B", "x", "4", false);
  ASSERT_EQ(eff.sections().size(), 2u);
  EXPECT_EQ(eff.sections()[0].name, "B");
  EXPECT_EQ(eff.sections()[1].name, "A");
  const auto& b = eff.sections()[0].entries;
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].key, "x");
  EXPECT_EQ(b[0].value, "4");
  EXPECT_FALSE(b[0].from_default);
  EXPECT_EQ(b[1].key, "z");
}

TEST(EffectiveConfig, ToIniTextMarksDefaultsAndWritesTheHeader) {
  EffectiveConfig eff;
  eff.record("PlanarEM", "sigma_m", "0.05", false);
  eff.record("PlanarEM", "max_iterations", "40", true);
  eff.record("Sensors", "label", "", true);
  EXPECT_EQ(eff.toIniText({"effective configuration"}),
            "# effective configuration\n"
            "\n[PlanarEM]\nsigma_m = 0.05\nmax_iterations = 40  ; default\n"
            "\n[Sensors]\nlabel =  ; default\n");
}

TEST(EffectiveConfig, ToIniTextReadsBackToTheSameValues) {
  const std::vector<std::string> values = {"",
                                           "plain",
                                           "two words",
                                           "  leading",
                                           "trailing  ",
                                           "\tTab",
                                           "a ; b",
                                           "a\t# b",
                                           "; starts",
                                           "#hash",
                                           "//slashes",
                                           "http://x/y",
                                           "a;b#c",
                                           "\"quoted\"",
                                           "\"",
                                           "mid \"q\" dle",
                                           "${HOME}",
                                           "$env{HOME}",
                                           "C:\\dir\\",
                                           "back\\\"slash",
                                           "= sign = here",
                                           "[not a section]",
                                           "@include x.ini",
                                           "1.0000000000000001e-01"};
  EffectiveConfig eff;
  for (std::size_t i = 0; i < values.size(); ++i) {
    eff.record("S", "k" + std::to_string(i), values[i], i % 2 == 0);
  }
  eff.record("T", "label", "x", false);
  const auto doc = IniDocument::parse(eff.toIniText({"header ; with # marks"}), "effective.ini");
  EXPECT_EQ(doc.sectionNames(), (std::vector<std::string>{"S", "T"}));
  for (std::size_t i = 0; i < values.size(); ++i) {
    const IniValue* v = doc.find("S", "k" + std::to_string(i));
    ASSERT_NE(v, nullptr) << i;
    EXPECT_EQ(v->value, values[i]) << "value #" << i << " written as:\n" << eff.toIniText();
  }
}

}  // namespace
}  // namespace pmap::config
