#include "pmap/common/text.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace pmap {

std::string trim(std::string_view s) {
  const char* ws = " \t\r\n";
  const auto b = s.find_first_not_of(ws);
  if (b == std::string_view::npos) {
    return {};
  }
  const auto e = s.find_last_not_of(ws);
  return std::string(s.substr(b, e - b + 1));
}

std::string toLower(std::string_view s) {
  std::string out(s);
  for (char& c : out) {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

std::vector<std::string> splitFields(std::string_view s, std::string_view separators) {
  std::vector<std::string> out;
  std::size_t pos = 0;
  while (pos < s.size()) {
    const auto b = s.find_first_not_of(separators, pos);
    if (b == std::string_view::npos) {
      break;
    }
    auto e = s.find_first_of(separators, b);
    if (e == std::string_view::npos) {
      e = s.size();
    }
    out.emplace_back(s.substr(b, e - b));
    pos = e;
  }
  return out;
}

std::optional<double> parseDouble(std::string_view s) {
  const std::string t = trim(s);
  if (t.empty()) {
    return std::nullopt;
  }
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(t.c_str(), &end);
  if (end != t.c_str() + t.size() || errno == ERANGE || !std::isfinite(v)) {
    return std::nullopt;
  }
  return v;
}

std::optional<std::int64_t> parseInt(std::string_view s) {
  const std::string t = trim(s);
  if (t.empty()) {
    return std::nullopt;
  }
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(t.c_str(), &end, 10);
  if (end != t.c_str() + t.size() || errno == ERANGE) {
    return std::nullopt;
  }
  return static_cast<std::int64_t>(v);
}

std::optional<bool> parseBool(std::string_view s) {
  const std::string t = toLower(trim(s));
  if (t == "true" || t == "yes" || t == "on" || t == "1") {
    return true;
  }
  if (t == "false" || t == "no" || t == "off" || t == "0") {
    return false;
  }
  return std::nullopt;
}

std::size_t editDistance(std::string_view a_in, std::string_view b_in) {
  const std::string a = toLower(a_in);
  const std::string b = toLower(b_in);
  std::vector<std::size_t> prev(b.size() + 1);
  std::vector<std::size_t> cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) {
    prev[j] = j;
  }
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t subst = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, subst});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string nearestWord(std::string_view word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const auto& c : candidates) {
    const std::size_t d = editDistance(word, c);
    if (d < best_d) {
      best_d = d;
      best = c;
    }
  }
  return best;
}

std::string oneLineError(std::string_view what) {
  std::string line;
  const auto msg = what.find("Message:");
  if (msg != std::string_view::npos) {
    const auto start = msg + 8;
    line = trim(what.substr(start, what.find('\n', start) - start));
  } else {
    std::size_t pos = 0;
    while (pos < what.size() && line.empty()) {
      const auto end = std::min(what.find('\n', pos), what.size());
      line = trim(what.substr(pos, end - pos));
      if (line.find("====") != std::string::npos) {
        line.clear();  // MRPT's banner line
      }
      pos = end + 1;
    }
  }
  return line.size() > 240 ? line.substr(0, 240) + "..." : line;
}

std::string escapeHtml(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string joinLines(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& l : lines) {
    out += (out.empty() ? "" : "\n") + l;
  }
  return out;
}

std::vector<std::string> splitLines(std::string_view text) {
  std::vector<std::string> lines;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const auto end = std::min(text.find('\n', pos), text.size());
    if (end > pos) {
      lines.emplace_back(text.substr(pos, end - pos));
    }
    pos = end + 1;
  }
  return lines;
}

}  // namespace pmap
