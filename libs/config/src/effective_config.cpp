#include "pmap/config/effective_config.h"

#include <sstream>

namespace pmap::config {

namespace {

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

/// True if IniDocument would not read `value` back unchanged when written
/// bare after "key = ": edge spaces, a leading quote, an inline comment
/// marker (';', '#', '//' at the start or after whitespace), a "${" or a
/// control character.
bool needsQuotes(const std::string& value) {
  if (value.empty()) {
    return false;
  }
  if (isSpace(value.front()) || isSpace(value.back()) || value.front() == '"') {
    return true;
  }
  for (std::size_t i = 0; i < value.size(); ++i) {
    const char c = value[i];
    const bool comment =
        c == ';' || c == '#' || (c == '/' && i + 1 < value.size() && value[i + 1] == '/');
    if (comment && (i == 0 || isSpace(value[i - 1]))) {
      return true;
    }
    if ((c == '$' && i + 1 < value.size() && value[i + 1] == '{') ||
        static_cast<unsigned char>(c) < 0x20) {
      return true;
    }
  }
  return false;
}

/// "..." with '"', '\' and '$' escaped by a backslash; line breaks (which an
/// ini line cannot hold) become spaces.
std::string quote(const std::string& value) {
  std::string out = "\"";
  for (char c : value) {
    if (c == '"' || c == '\\' || c == '$') {
      out += '\\';
    }
    out += (c == '\n' || c == '\r') ? ' ' : c;
  }
  return out + "\"";
}

/// Writes `text` as comment lines, one per line of the text.
void writeComment(std::ostringstream& out, const std::string& text) {
  std::istringstream in(text);
  std::string line;
  bool any = false;
  while (std::getline(in, line)) {
    out << (line.empty() ? "#" : "# " + line) << "\n";
    any = true;
  }
  if (!any) {
    out << "#\n";
  }
}

}  // namespace

void EffectiveConfig::record(const std::string& section, const std::string& key,
                             const std::string& value, bool from_default) {
  Section* sec = nullptr;
  for (auto& s : sections_) {
    if (s.name == section) {
      sec = &s;
      break;
    }
  }
  if (sec == nullptr) {
    sections_.push_back(Section{section, {}});
    sec = &sections_.back();
  }
  for (auto& e : sec->entries) {
    if (e.key == key) {
      e.value = value;
      e.from_default = from_default;
      return;
    }
  }
  sec->entries.push_back(Entry{key, value, from_default});
}

std::string EffectiveConfig::toIniText(const std::vector<std::string>& header) const {
  std::ostringstream out;
  for (const auto& h : header) {
    writeComment(out, h);
  }
  for (std::size_t i = 0; i < sections_.size(); ++i) {
    const Section& sec = sections_[i];
    if (i > 0 || !header.empty()) {
      out << "\n";
    }
    out << "[" << sec.name << "]\n";
    for (const Entry& e : sec.entries) {
      out << e.key << " =";
      if (!e.value.empty()) {
        out << " " << (needsQuotes(e.value) ? quote(e.value) : e.value);
      }
      if (e.from_default) {
        out << "  ; default";
      }
      out << "\n";
    }
  }
  return out.str();
}

}  // namespace pmap::config
