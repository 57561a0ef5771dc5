// Strict, typed reading of one project section of an IniDocument.
//
//   SectionReader r(doc, "PlanarEM", &effective);
//   r.read("sigma_m", opts.sigma_m);      // absent: keeps the default
//   r.finish();                            // unknown keys -> ConfigError
//
// Every error is a ConfigError naming file:line, [section] and key; an
// unknown key suggests the nearest known one.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "pmap/config/effective_config.h"
#include "pmap/config/ini_document.h"

namespace pmap::config {

enum class Presence { kRequired, kOptional };

class SectionReader {
 public:
  /// Throws ConfigError "<file>: missing section [name]" (with the nearest
  /// section name suggested) when `presence` is kRequired and it is absent.
  SectionReader(const IniDocument& doc, std::string section, EffectiveConfig* effective = nullptr,
                Presence presence = Presence::kRequired);

  bool present() const { return present_; }
  const std::string& section() const { return section_; }

  /// Reads `key` into `value` if present (strict parse, see common/text.h);
  /// keeps `value` (the default) otherwise. Records the effective value.
  void read(const std::string& key, double& value);
  void read(const std::string& key, int& value);
  void read(const std::string& key, std::int64_t& value);
  void read(const std::string& key, bool& value);
  void read(const std::string& key, std::string& value);
  /// Comma-separated list; items are trimmed; an empty value is a list with
  /// one empty item (the empty string is a valid sensor label).
  void read(const std::string& key, std::vector<std::string>& value);
  /// A number, or the word `auto` (any case): then `is_auto` is set and
  /// `value` keeps its default.
  void readNumberOrAuto(const std::string& key, double& value, bool& is_auto);

  /// Throws ConfigError "<file:line>: [section] key = value: <rule>".
  [[noreturn]] void fail(const std::string& key, const std::string& rule) const;

  /// Throws one ConfigError listing (a line each) every value read() could
  /// not parse and every key of the section that no read() asked for:
  /// "<file:line>: [section] unknown key 'sigam_m' (did you mean 'sigma_m'?)".
  /// A value that did not parse leaves the default in place until then.
  void finish() const;

 private:
  const IniValue* lookup(const std::string& key);
  void record(const std::string& key, const std::string& value, bool from_default);
  void parseError(const std::string& key, const IniValue& v, const std::string& what);

  const IniDocument& doc_;
  std::string section_;
  EffectiveConfig* effective_;
  bool present_ = false;
  std::vector<std::string> known_keys_;
  std::map<std::string, std::string> recorded_;  ///< key -> effective value text
  std::vector<std::string> errors_;              ///< values that did not parse
};

/// Loads an options struct: calls `opts.load(reader)`, `reader.finish()`,
/// then `opts.validate(&why)`; a failed validation becomes a ConfigError
/// naming the file and section. T provides:
///   void load(SectionReader&);
///   bool validate(std::string* why) const;   // Ceres-style
void throwInvalidOptions(const IniDocument& doc, const std::string& section,
                         const std::string& why);

template <class T>
void loadOptions(const IniDocument& doc, const std::string& section, T& opts,
                 EffectiveConfig* effective, Presence presence = Presence::kRequired) {
  SectionReader reader(doc, section, effective, presence);
  opts.load(reader);
  reader.finish();
  std::string why;
  if (!opts.validate(&why)) {
    throwInvalidOptions(doc, section, why);
  }
}

}  // namespace pmap::config
