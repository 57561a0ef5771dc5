// A parsed ini file in MRPT's syntax, read strictly.
//
// Syntax (mrpt::config::CConfigFile's, read strictly; quoting is an addition):
//   [Section]                 section header
//   key = value               key/value; the value may be empty; inline
//                             comments start with ';', '#' or '//' at the
//                             start or after whitespace (http://x is kept)
//   key = "  value ; x"       quoted: keeps edge spaces and comment
//                             characters; \" \\ \$ are escapes; "" is empty
//   ; comment, # comment, // comment     whole-line comments
//   @include FILE             includes FILE (relative to the including file),
//                             textually: the current section carries on
//   @define NAME VALUE        defines ${NAME}, substituted in later values
// Names are case-sensitive. A section reopened later merges. BOM, CRLF line
// ends, tabs and trailing spaces are accepted. A missing file, a missing
// @include target, an include cycle or nesting deeper than 16, a malformed
// line, a key outside any section, a duplicate key in one section and an
// undefined ${NAME} are one-line ConfigErrors "<file>:<line>: <what>".
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace pmap::config {

/// One key's value and where it was written.
struct IniValue {
  std::string value;
  std::string file;  ///< file the line came from (after @include)
  int line = 0;      ///< 1-based line number
};

class IniDocument {
 public:
  /// Reads and parses `path`. Throws ConfigError.
  static IniDocument load(const std::filesystem::path& path);
  /// Parses `text`; `origin` names it in messages, @include resolves relative
  /// to `base_dir`. Throws ConfigError.
  static IniDocument parse(const std::string& text, const std::string& origin,
                           const std::filesystem::path& base_dir = ".");

  /// Name of the top-level file (or the `origin` given to parse()).
  const std::string& origin() const { return origin_; }
  /// Section names in order of first appearance.
  const std::vector<std::string>& sectionNames() const { return section_order_; }
  bool hasSection(const std::string& section) const;
  /// Keys of `section` in file order (empty if the section is absent).
  std::vector<std::string> keys(const std::string& section) const;
  /// The value of section/key, or nullptr.
  const IniValue* find(const std::string& section, const std::string& key) const;
  /// "file:line" of section/key, or the document origin when absent.
  std::string location(const std::string& section, const std::string& key) const;

 private:
  struct Section {
    std::vector<std::string> key_order;
    std::map<std::string, IniValue> values;
    std::string file;
    int line = 0;
  };
  std::string origin_;
  std::vector<std::string> section_order_;
  std::map<std::string, Section> sections_;

  friend class IniParser;
};

}  // namespace pmap::config
