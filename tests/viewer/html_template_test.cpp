#include "pmap/viewer/html_template.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <stdexcept>

namespace pmap::viewer {
namespace {

TEST(FillTemplate, ReplacesEveryPlaceholder) {
  EXPECT_EQ(fillTemplate("<b>{{A}}</b>{{B_2}}{{A}}", {{"A", "x"}, {"B_2", "yy"}}), "<b>x</b>yyx");
}

TEST(FillTemplate, EmptyTemplateAndNoValues) {
  EXPECT_EQ(fillTemplate("", {}), "");
}

TEST(FillTemplate, ValuesAreNotScannedAgain) {
  EXPECT_EQ(fillTemplate("{{JS}};{{B}}", {{"JS", "a={{B}}"}, {"B", "b"}}), "a={{B}};b");
}

TEST(FillTemplate, LeavesOtherBracesAlone) {
  EXPECT_EQ(fillTemplate("{{ x }} {{}} {{lower}} {{A} {{A}}", {{"A", "1"}}),
            "{{ x }} {{}} {{lower}} {{A} 1");
}

TEST(FillTemplate, MissingValueIsAnError) {
  EXPECT_THROW(fillTemplate("{{A}}{{B}}", {{"A", "1"}}), std::invalid_argument);
}

TEST(FillTemplate, UnusedValueIsAnError) {
  EXPECT_THROW(fillTemplate("{{A}}", {{"A", "1"}, {"B", "2"}}), std::invalid_argument);
}

TEST(EscapeJsonForScript, CannotCloseTheScriptAndParsesBack) {
  const nlohmann::json value = {{"title", "</script><!-- & >"}};
  const std::string text = escapeJsonForScript(value.dump());
  EXPECT_EQ(text.find('<'), std::string::npos);
  EXPECT_EQ(text.find('>'), std::string::npos);
  EXPECT_EQ(nlohmann::json::parse(text), value);
}

}  // namespace
}  // namespace pmap::viewer
