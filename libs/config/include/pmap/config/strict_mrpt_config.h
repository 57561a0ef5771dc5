// MRPT's own option loaders (CICP::TConfigParams, CMetricMapBuilderICP::
// TConfigParams, TSetOfMetricMapInitializers, ...) read a CConfigFileBase
// leniently: "abc" reads as 0, misspelled keys are ignored. This adapter
// exposes selected sections of an IniDocument to those loaders and makes
// them strict:
//  - every key the loaders read is recorded (with the value in force, into
//    the EffectiveConfig);
//  - a value present in the file must parse as the type the loader's default
//    implies (number, bool) — checked when read, reported by checkAllRead();
//    a bad value reaches MRPT as the default; bool spellings (on/off, yes/no,
//    true/false) reach MRPT as 1/0 (MRPT itself reads "on" as false);
//  - after the loaders ran, checkAllRead() reports any key present in an
//    owned section that no loader read (nearest read key suggested), and any
//    non-empty owned section that no loader read at all; keys that only
//    MRPT's applications read (rawlog_file, SHOW_*, ...: isMrptAppKey) are
//    accepted and returned, so that an icp-slam ini can be reused.
// The document is read-only: clear() only drops values written through this
// object.
#pragma once

#include <mrpt/config/CConfigFileBase.h>

#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "pmap/config/effective_config.h"
#include "pmap/config/ini_document.h"

namespace pmap::config {

/// True for keys that MRPT's applications (icp-slam) read themselves and no
/// MRPT option loader does: rawlog_file, logOutput_dir, SHOW_*, ...
bool isMrptAppKey(const std::string& key);

class StrictMrptConfig : public mrpt::config::CConfigFileBase {
 public:
  /// `owned` lists section names; an entry ending in '*' is a prefix
  /// ("MappingApplication*" owns MappingApplication and its sub-sections).
  StrictMrptConfig(const IniDocument& doc, std::vector<std::string> owned,
                   EffectiveConfig* effective = nullptr);

  /// Throws ConfigError if `section` is absent from the document.
  void requireSection(const std::string& section) const;

  /// Throws one ConfigError listing every problem (a line each): values that
  /// did not parse as their expected type, keys nobody read. Returns the
  /// MRPT application keys it accepted ("[section] key"), for one warning.
  std::vector<std::string> checkAllRead() const;

  /// For a catch block around an MRPT loader (MRPT's read_enum throws on an
  /// unknown name, without file or line): throws the first recorded read
  /// error if any, else a ConfigError naming file:line, section and key of
  /// the last key read, with the first line of MRPT's message.
  [[noreturn]] void throwLoaderError(const std::exception& e) const;

  void getAllSections(std::vector<std::string>& sections) const override;
  void getAllKeys(const std::string& section, std::vector<std::string>& keys) const override;
  void clear() override;

 protected:
  void writeString(const std::string& section, const std::string& name,
                   const std::string& str) override;
  std::string readString(const std::string& section, const std::string& name,
                         const std::string& defaultStr, bool failIfNotFound = false) const override;

 private:
  bool owns(const std::string& section) const;
  /// "'key'" read in `section`, or "'key' in [other]" read in another owned
  /// section, nearest to `key`; empty if none is close.
  std::string suggestKey(const std::string& section, const std::string& key) const;

  const IniDocument& doc_;
  std::vector<std::string> owned_;
  EffectiveConfig* effective_;
  std::map<std::string, std::map<std::string, std::string>> written_;
  mutable std::map<std::string, std::set<std::string>> read_keys_;
  mutable std::vector<std::string> type_errors_;
  mutable std::string last_section_;  ///< section and key of the last read
  mutable std::string last_key_;
};

}  // namespace pmap::config
