// Fills a page template whose placeholders are "{{NAME}}" (NAME: capitals,
// digits, underscores), in one pass: the values are never scanned again, so a
// value may itself contain "{{" (a JS bundle often does).
#pragma once

#include <map>
#include <string>
#include <string_view>

namespace pmap::viewer {

/// `text` with every placeholder replaced by values.at(NAME). Throws
/// std::invalid_argument naming the placeholder if a placeholder has no value
/// or a value has no placeholder.
std::string fillTemplate(std::string_view text, const std::map<std::string, std::string>& values);

/// JSON text made safe inside a <script> element: '<', '>' and '&' (which
/// JSON allows only inside strings) become \u003c, \u003e and \u0026, so
/// neither "</script" nor "<!--" can appear; JSON.parse reads the same value.
std::string escapeJsonForScript(std::string_view json);

}  // namespace pmap::viewer
