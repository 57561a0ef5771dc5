#include "pmap/config/ini_document.h"

#include <cstdint>
#include <fstream>
#include <iterator>
#include <sstream>
#include <system_error>

#include "pmap/common/error.h"
#include "pmap/common/text.h"

namespace pmap::config {

namespace fs = std::filesystem;

namespace {

constexpr int kMaxIncludeDepth = 16;
constexpr std::size_t kMaxQuotedLineChars = 60;
const char* const kBom = "\xEF\xBB\xBF";

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

/// Position of the first inline comment (';', '#' or '//' at the start or
/// preceded by whitespace), or npos.
std::size_t findComment(const std::string& s) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    const bool starts =
        s[i] == ';' || s[i] == '#' || (s[i] == '/' && i + 1 < s.size() && s[i + 1] == '/');
    if (starts && (i == 0 || isSpace(s[i - 1]))) {
      return i;
    }
  }
  return std::string::npos;
}

std::string stripComment(const std::string& s) {
  const auto c = findComment(s);
  return trim(c == std::string::npos ? s : s.substr(0, c));
}

/// The line as shown in a message: control characters escaped, long lines cut.
std::string quoteLine(const std::string& line) {
  std::string out;
  for (char c : line) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      static const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[(static_cast<unsigned char>(c) >> 4) & 0xf];
      out += hex[static_cast<unsigned char>(c) & 0xf];
    } else {
      out += c;
    }
    if (out.size() > kMaxQuotedLineChars) {
      out += "...";
      break;
    }
  }
  return "'" + out + "'";
}

// An ini larger than this is not a configuration (and /dev/zero never ends).
constexpr std::uintmax_t kMaxIniBytes = 4u << 20;

bool readFile(const fs::path& path, std::string* text, std::string* why) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    *why = "cannot open file (it is a directory)";
    return false;
  }
  if (fs::exists(path, ec) && !fs::is_regular_file(path, ec)) {
    *why = "not a regular file (a device, FIFO or socket)";
    return false;
  }
  if (fs::exists(path, ec) && fs::file_size(path, ec) > kMaxIniBytes) {
    *why = "file larger than 4 MiB, not an ini file";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    *why = "cannot open file";
    return false;
  }
  text->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (in.bad()) {
    *why = "cannot read file";
    return false;
  }
  return true;
}

}  // namespace

/// Parses one file's text into an IniDocument; follows @include textually
/// (the current section carries over into and out of the included file).
class IniParser {
 public:
  explicit IniParser(IniDocument* doc) : doc_(doc) {}

  void parseText(std::string text, const std::string& file, const fs::path& base_dir,
                 const fs::path& identity, int depth);

 private:
  void parseLine(const std::string& line);
  void parseSection(const std::string& line);
  void parseDirective(const std::string& line);
  void parseInclude(const std::string& arg);
  void parseKeyValue(const std::string& line, std::size_t eq);
  std::string unquote(const std::string& raw);
  std::string substitute(const std::string& value, bool in_quotes);
  [[noreturn]] void fail(const std::string& what) const;
  [[noreturn]] void malformed(const std::string& line, const std::string& expected) const;

  IniDocument* doc_;
  std::string section_;  // current section, empty before the first header
  std::map<std::string, std::string> defines_;
  std::vector<fs::path> stack_;  // files being parsed, for cycle detection
  std::string file_;
  fs::path base_dir_;
  int line_no_ = 0;
  int depth_ = 0;
};

void IniParser::fail(const std::string& what) const {
  throw ConfigError(file_ + ":" + std::to_string(line_no_) + ": " + what);
}

void IniParser::malformed(const std::string& line, const std::string& expected) const {
  fail("malformed line " + quoteLine(line) + " (" + expected + ")");
}

void IniParser::parseText(std::string text, const std::string& file, const fs::path& base_dir,
                          const fs::path& identity, int depth) {
  if (text.compare(0, 3, kBom) == 0) {
    text.erase(0, 3);
  }
  const std::string saved_file = file_;
  const fs::path saved_dir = base_dir_;
  const int saved_line = line_no_;
  const int saved_depth = depth_;
  file_ = file;
  base_dir_ = base_dir;
  depth_ = depth;
  stack_.push_back(identity);
  std::istringstream in(text);
  std::string line;
  line_no_ = 0;
  while (std::getline(in, line)) {
    ++line_no_;
    parseLine(trim(line));
  }
  stack_.pop_back();
  file_ = saved_file;
  base_dir_ = saved_dir;
  line_no_ = saved_line;
  depth_ = saved_depth;
}

void IniParser::parseLine(const std::string& line) {
  if (line.empty() || findComment(line) == 0) {
    return;
  }
  if (line[0] == '[') {
    parseSection(line);
  } else if (line[0] == '@') {
    parseDirective(line);
  } else {
    const auto eq = line.find('=');
    if (eq == std::string::npos) {
      malformed(line, "expected 'key = value', '[Section]' or a comment");
    }
    parseKeyValue(line, eq);
  }
}

void IniParser::parseSection(const std::string& line) {
  const std::string text = stripComment(line);
  const auto close = text.find(']');
  if (close == std::string::npos || close + 1 != text.size()) {
    malformed(line, "expected '[Section]'");
  }
  const std::string name = trim(text.substr(1, close - 1));
  if (name.empty() || name.find('[') != std::string::npos) {
    malformed(line, "expected a non-empty section name in '[Section]'");
  }
  section_ = name;
  auto [it, inserted] = doc_->sections_.try_emplace(name);
  if (inserted) {
    it->second.file = file_;
    it->second.line = line_no_;
    doc_->section_order_.push_back(name);
  }
}

void IniParser::parseDirective(const std::string& line) {
  const auto sp = line.find_first_of(" \t");
  const std::string word = line.substr(0, sp);
  const std::string arg = sp == std::string::npos ? std::string() : trim(line.substr(sp));
  if (word == "@include") {
    parseInclude(arg);
  } else if (word == "@define") {
    const auto nsp = arg.find_first_of(" \t");
    const std::string name = arg.substr(0, nsp);
    if (name.empty() || findComment(name) == 0) {
      malformed(line, "expected '@define NAME VALUE'");
    }
    defines_[name] = nsp == std::string::npos ? std::string() : unquote(trim(arg.substr(nsp)));
  } else {
    fail("unknown directive '" + word + "' (expected @include or @define)");
  }
}

void IniParser::parseInclude(const std::string& arg) {
  const std::string name = unquote(arg);
  if (name.empty()) {
    fail("@include without a file name");
  }
  const std::string prefix = "@include '" + name + "': ";
  if (depth_ + 1 > kMaxIncludeDepth) {
    fail(prefix + "includes nested deeper than " + std::to_string(kMaxIncludeDepth) + " levels");
  }
  const fs::path path = (base_dir_ / fs::path(name)).lexically_normal();
  std::error_code ec;
  const fs::path identity = fs::weakly_canonical(path, ec);
  for (const auto& open : stack_) {
    if (!ec && open == identity) {
      fail(prefix + "include cycle (the file is already being read)");
    }
  }
  std::string text;
  std::string why;
  if (!readFile(path, &text, &why)) {
    fail(prefix + why);
  }
  parseText(std::move(text), path.string(), path.parent_path(), ec ? path : identity, depth_ + 1);
}

void IniParser::parseKeyValue(const std::string& line, std::size_t eq) {
  const std::string key = trim(line.substr(0, eq));
  if (key.empty() || key.find_first_of(" \t[]\"") != std::string::npos) {
    malformed(line, "expected 'key = value' with a key without spaces, brackets or quotes");
  }
  if (section_.empty()) {
    fail("key '" + key + "' outside any section (add a '[Section]' line above it)");
  }
  const std::string value = unquote(trim(line.substr(eq + 1)));
  auto& sec = doc_->sections_[section_];
  const auto found = sec.values.find(key);
  if (found != sec.values.end()) {
    const IniValue& first = found->second;
    const std::string where = first.file == file_ ? "line " + std::to_string(first.line)
                                                  : first.file + ":" + std::to_string(first.line);
    fail("duplicate key '" + key + "' in [" + section_ + "] (first at " + where + ")");
  }
  sec.key_order.push_back(key);
  sec.values.emplace(key, IniValue{value, file_, line_no_});
}

/// The value of a trimmed raw right-hand side: quoted ("..." with \" \\ \$
/// escapes) or bare (cut at an inline comment); ${NAME} substituted.
std::string IniParser::unquote(const std::string& raw) {
  if (raw.empty() || raw[0] != '"') {
    return substitute(stripComment(raw), false);
  }
  std::string body;
  std::size_t i = 1;
  for (; i < raw.size() && raw[i] != '"'; ++i) {
    // body keeps every literal backslash escaped; substitute() resolves them.
    if (raw[i] == '\\' && i + 1 < raw.size() &&
        (raw[i + 1] == '"' || raw[i + 1] == '\\' || raw[i + 1] == '$')) {
      body += '\\';
      ++i;
    } else if (raw[i] == '\\') {
      body += '\\';  // a lone backslash is literal
    }
    body += raw[i];
  }
  if (i >= raw.size()) {
    fail("unterminated quoted value " + quoteLine(raw));
  }
  const std::string rest = trim(raw.substr(i + 1));
  if (!rest.empty() && findComment(rest) != 0) {
    fail("unexpected text " + quoteLine(rest) + " after the closing quote");
  }
  return substitute(body, true);
}

std::string IniParser::substitute(const std::string& value, bool in_quotes) {
  std::string out;
  for (std::size_t i = 0; i < value.size(); ++i) {
    if (in_quotes && value[i] == '\\' && i + 1 < value.size()) {
      out += value[++i];  // escaped by unquote(): \" \\ or \$
      continue;
    }
    if (value[i] != '$' || i + 1 >= value.size() || value[i + 1] != '{') {
      out += value[i];
      continue;
    }
    const auto close = value.find('}', i + 2);
    if (close == std::string::npos) {
      fail("unterminated '${' in value " + quoteLine(value));
    }
    const std::string name = value.substr(i + 2, close - i - 2);
    const auto def = defines_.find(name);
    if (def == defines_.end()) {
      fail("undefined variable '${" + name + "}' (no @define " + name + " above)");
    }
    out += def->second;
    i = close;
  }
  return out;
}

IniDocument IniDocument::load(const fs::path& path) {
  std::string text;
  std::string why;
  if (!readFile(path, &text, &why)) {
    throw ConfigError(path.string() + ": " + why);
  }
  IniDocument doc;
  doc.origin_ = path.string();
  std::error_code ec;
  const fs::path identity = fs::weakly_canonical(path, ec);
  IniParser(&doc).parseText(std::move(text), doc.origin_, path.parent_path(), ec ? path : identity,
                            0);
  return doc;
}

IniDocument IniDocument::parse(const std::string& text, const std::string& origin,
                               const fs::path& base_dir) {
  IniDocument doc;
  doc.origin_ = origin;
  IniParser(&doc).parseText(text, origin, base_dir, fs::path(), 0);
  return doc;
}

bool IniDocument::hasSection(const std::string& section) const {
  return sections_.count(section) != 0;
}

std::vector<std::string> IniDocument::keys(const std::string& section) const {
  const auto it = sections_.find(section);
  return it == sections_.end() ? std::vector<std::string>() : it->second.key_order;
}

const IniValue* IniDocument::find(const std::string& section, const std::string& key) const {
  const auto sec = sections_.find(section);
  if (sec == sections_.end()) {
    return nullptr;
  }
  const auto it = sec->second.values.find(key);
  return it == sec->second.values.end() ? nullptr : &it->second;
}

std::string IniDocument::location(const std::string& section, const std::string& key) const {
  const IniValue* v = find(section, key);
  return v ? v->file + ":" + std::to_string(v->line) : origin_;
}

}  // namespace pmap::config
