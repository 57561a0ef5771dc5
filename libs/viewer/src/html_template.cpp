#include "pmap/viewer/html_template.h"

#include <set>
#include <stdexcept>

namespace pmap::viewer {
namespace {

bool isNameChar(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

/// Length of the placeholder starting at `pos` ("{{NAME}}"), 0 if none starts there.
std::size_t placeholderLength(std::string_view text, std::size_t pos) {
  if (text.compare(pos, 2, "{{") != 0) {
    return 0;
  }
  std::size_t end = pos + 2;
  while (end < text.size() && isNameChar(text[end])) {
    ++end;
  }
  if (end == pos + 2 || text.compare(end, 2, "}}") != 0) {
    return 0;
  }
  return end + 2 - pos;
}

}  // namespace

std::string fillTemplate(std::string_view text, const std::map<std::string, std::string>& values) {
  std::string out;
  std::set<std::string> used;
  std::size_t copied = 0;
  for (std::size_t pos = text.find("{{"); pos != std::string_view::npos;
       pos = text.find("{{", pos + 1)) {
    const std::size_t length = placeholderLength(text, pos);
    if (length == 0) {
      continue;
    }
    const std::string name(text.substr(pos + 2, length - 4));
    const auto value = values.find(name);
    if (value == values.end()) {
      throw std::invalid_argument("page template: no value for placeholder {{" + name + "}}");
    }
    out.append(text.substr(copied, pos - copied)).append(value->second);
    used.insert(name);
    copied = pos + length;
    pos = copied - 1;
  }
  out.append(text.substr(copied));
  for (const auto& [name, value] : values) {
    if (used.count(name) == 0) {
      throw std::invalid_argument("page template: no placeholder {{" + name + "}}");
    }
  }
  return out;
}

std::string escapeJsonForScript(std::string_view json) {
  std::string out;
  out.reserve(json.size());
  for (const char c : json) {
    switch (c) {
      case '<':
        out += "\\u003c";
        break;
      case '>':
        out += "\\u003e";
        break;
      case '&':
        out += "\\u0026";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace pmap::viewer
