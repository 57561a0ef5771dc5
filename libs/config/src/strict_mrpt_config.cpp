#include "pmap/config/strict_mrpt_config.h"

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "pmap/common/error.h"
#include "pmap/common/text.h"
#include "pmap/config/section_reader.h"

namespace pmap::config {

namespace {

// The type a loader expects, inferred from the default string that
// CConfigFileBase's typed reads pass to readString() (measured on MRPT 2.5.8):
//   read_double   "%.16e"  e.g. 1.0000000000000001e-01
//   read_float    "%.10e"  e.g. 1.0000000149e-01
//   read_int, read_uint64_t   decimal, e.g. 40
//   read_bool     "1" / "0"   (indistinguishable from an int default of 1 / 0)
//   read_string, read_string_first_word   the default itself
//   read_enum, read_vector, read_matrix   "" (any value accepted here)
enum class Expected { kAny, kBoolOrInt, kInt, kDouble, kFloat };

bool isDigit(char c) {
  return c >= '0' && c <= '9';
}

bool isDecimalInteger(const std::string& s) {
  std::size_t i = (!s.empty() && s[0] == '-') ? 1 : 0;
  if (i >= s.size()) {
    return false;
  }
  for (; i < s.size(); ++i) {
    if (!isDigit(s[i])) {
      return false;
    }
  }
  return true;
}

/// True if `s` is "[-]d.<mantissa_digits digits>e(+|-)dd[d]", printf's "%.Ne".
bool isScientific(const std::string& s, std::size_t mantissa_digits) {
  std::size_t i = (!s.empty() && s[0] == '-') ? 1 : 0;
  if (s.size() < i + 2 || !isDigit(s[i]) || s[i + 1] != '.') {
    return false;
  }
  i += 2;
  for (std::size_t n = 0; n < mantissa_digits; ++n, ++i) {
    if (i >= s.size() || !isDigit(s[i])) {
      return false;
    }
  }
  if (i + 3 > s.size() || s[i] != 'e' || (s[i + 1] != '+' && s[i + 1] != '-')) {
    return false;
  }
  for (i += 2; i < s.size(); ++i) {
    if (!isDigit(s[i])) {
      return false;
    }
  }
  return true;
}

Expected inferExpected(const std::string& default_str) {
  if (default_str == "0" || default_str == "1") {
    return Expected::kBoolOrInt;
  }
  if (isDecimalInteger(default_str)) {
    return Expected::kInt;
  }
  if (isScientific(default_str, 16)) {
    return Expected::kDouble;
  }
  if (isScientific(default_str, 10)) {
    return Expected::kFloat;
  }
  return Expected::kAny;
}

bool looksLikeInteger(const std::string& s) {
  const std::string t = trim(s);
  return isDecimalInteger(!t.empty() && t[0] == '+' ? t.substr(1) : t);
}

std::string intError(const std::string& text) {
  if (looksLikeInteger(text)) {
    return "out of range for int";
  }
  return parseDouble(text) ? "not an integer" : "not a number";
}

bool fitsInt(std::int64_t v) {
  return v >= std::numeric_limits<int>::min() && v <= std::numeric_limits<int>::max();
}

/// Checks `text` against `type`. Returns the error ("" if none) and sets
/// `to_mrpt` to the text MRPT must see (bool spellings become "1"/"0": MRPT's
/// read_bool reads "on" as false).
std::string checkValue(const std::string& text, Expected type, std::string* to_mrpt) {
  *to_mrpt = trim(text);
  switch (type) {
    case Expected::kAny:
      *to_mrpt = text;
      return {};
    case Expected::kInt: {
      const auto v = parseInt(text);
      return v && fitsInt(*v) ? std::string() : intError(text);
    }
    case Expected::kDouble:
      return parseDouble(text) ? std::string() : "not a number";
    case Expected::kFloat: {
      const auto v = parseDouble(text);
      if (!v) {
        return "not a number";
      }
      return std::fabs(*v) <= FLT_MAX ? std::string() : "out of range for float";
    }
    case Expected::kBoolOrInt:
      break;
  }
  if (const auto v = parseInt(text)) {
    return fitsInt(*v) ? std::string() : "out of range for int";
  }
  if (const auto b = parseBool(text)) {
    *to_mrpt = *b ? "1" : "0";
    return {};
  }
  return "not a boolean or an integer (expected true/false, yes/no, on/off, 1/0 or an integer)";
}

/// Shortest "%.*g" text that reads back as the same double (or float).
std::string shortestRoundTrip(double v, bool as_float) {
  char buf[64];
  if (v == std::trunc(v) && std::fabs(v) < 1e7) {
    std::snprintf(buf, sizeof(buf), "%.0f", v);  // 80 rather than 8e+01
    return buf;
  }
  for (int precision = 1; precision <= 17; ++precision) {
    std::snprintf(buf, sizeof(buf), "%.*g", precision, v);
    const double back = std::strtod(buf, nullptr);
    if (as_float ? static_cast<float>(back) == static_cast<float>(v) : back == v) {
      break;
    }
  }
  return buf;
}

/// The default as a person would write it: 0.1 rather than 1.0000000149e-01.
std::string displayDefault(const std::string& default_str, Expected type) {
  if (type == Expected::kDouble || type == Expected::kFloat) {
    return shortestRoundTrip(std::strtod(default_str.c_str(), nullptr), type == Expected::kFloat);
  }
  return default_str;
}

}  // namespace

bool isMrptAppKey(const std::string& key) {
  // Read by MRPT's icp-slam application itself (where the rawlog is, what to
  // show and log), or by older MRPT versions (onlyClosestCorrespondences,
  // likelihoodMapSelection), never by MRPT 2.5.8's option loaders: found in
  // the shipped /usr/share/mrpt/config_files/icp-slam/*.ini.
  static const char* const kKeys[] = {"rawlog_file",
                                      "rawlog_offset",
                                      "logOutput_dir",
                                      "LOG_FREQUENCY",
                                      "SAVE_POSE_LOG",
                                      "SAVE_3D_SCENE",
                                      "CAMERA_3DSCENE_FOLLOWS_ROBOT",
                                      "SHOW_PROGRESS_3D_REAL_TIME",
                                      "SHOW_PROGRESS_3D_REAL_TIME_DELAY_MS",
                                      "SHOW_LASER_SCANS_3D",
                                      "onlyClosestCorrespondences",
                                      "likelihoodMapSelection"};
  for (const char* k : kKeys) {
    if (key == k) {
      return true;
    }
  }
  return false;
}

StrictMrptConfig::StrictMrptConfig(const IniDocument& doc, std::vector<std::string> owned,
                                   EffectiveConfig* effective)
    : doc_(doc), owned_(std::move(owned)), effective_(effective) {}

bool StrictMrptConfig::owns(const std::string& section) const {
  for (const auto& o : owned_) {
    if (!o.empty() && o.back() == '*') {
      if (section.compare(0, o.size() - 1, o, 0, o.size() - 1) == 0) {
        return true;
      }
    } else if (o == section) {
      return true;
    }
  }
  return false;
}

void StrictMrptConfig::requireSection(const std::string& section) const {
  const SectionReader check(doc_, section, nullptr, Presence::kRequired);  // throws if absent
  (void)check;
}

std::string StrictMrptConfig::readString(const std::string& section, const std::string& name,
                                         const std::string& defaultStr, bool failIfNotFound) const {
  read_keys_[section].insert(name);
  last_section_ = section;
  last_key_ = name;
  const auto ws = written_.find(section);
  if (ws != written_.end() && ws->second.count(name) != 0) {
    return ws->second.at(name);
  }
  const Expected type = inferExpected(defaultStr);
  const IniValue* v = doc_.find(section, name);
  if (v == nullptr) {
    if (failIfNotFound) {
      const std::string msg =
          doc_.origin() + ": [" + section + "] missing required key '" + name + "'";
      type_errors_.push_back(msg);
      throw ConfigError(msg);  // MRPT's contract for failIfNotFound
    }
    if (effective_ != nullptr) {
      effective_->record(section, name, displayDefault(defaultStr, type), true);
    }
    return defaultStr;
  }
  if (effective_ != nullptr) {
    effective_->record(section, name, v->value, false);
  }
  std::string to_mrpt;
  const std::string error = checkValue(v->value, type, &to_mrpt);
  if (!error.empty()) {
    // Not thrown: MRPT may catch. Reported by checkAllRead().
    type_errors_.push_back(v->file + ":" + std::to_string(v->line) + ": [" + section + "] " + name +
                           " = '" + v->value + "': " + error);
    return defaultStr;
  }
  return to_mrpt;
}

std::vector<std::string> StrictMrptConfig::checkAllRead() const {
  std::vector<std::string> errors = type_errors_;
  std::vector<std::string> app_keys;
  for (const auto& section : doc_.sectionNames()) {
    const auto keys = doc_.keys(section);
    if (!owns(section) || keys.empty()) {
      continue;
    }
    const auto read = read_keys_.find(section);
    for (const auto& key : keys) {
      if (read != read_keys_.end() && read->second.count(key) != 0) {
        continue;
      }
      if (isMrptAppKey(key)) {
        app_keys.push_back("[" + section + "] " + key);
        continue;
      }
      if (read == read_keys_.end()) {
        errors.push_back(doc_.location(section, key) + ": [" + section +
                         "]: section not read by any MRPT loader");
        break;
      }
      std::string msg =
          doc_.location(section, key) + ": [" + section + "] unknown key '" + key + "'";
      const std::string hint = suggestKey(section, key);
      errors.push_back(hint.empty() ? msg : msg + " (did you mean " + hint + "?)");
    }
  }
  if (!errors.empty()) {
    throw ConfigError(joinLines(errors));
  }
  return app_keys;
}

void StrictMrptConfig::throwLoaderError(const std::exception& e) const {
  if (!type_errors_.empty()) {
    throw ConfigError(type_errors_.front());
  }
  const std::string what = oneLineError(e.what());
  if (last_key_.empty()) {
    throw ConfigError(doc_.origin() + ": MRPT loader failed: " + what);
  }
  const IniValue* v = doc_.find(last_section_, last_key_);
  const std::string shown = v ? last_key_ + " = '" + v->value + "'" : last_key_ + " (default)";
  throw ConfigError(doc_.location(last_section_, last_key_) + ": [" + last_section_ + "] " + shown +
                    ": " + what);
}

std::string StrictMrptConfig::suggestKey(const std::string& section, const std::string& key) const {
  const auto& same = read_keys_.at(section);
  const std::string near = nearestWord(key, {same.begin(), same.end()});
  if (!near.empty()) {
    return "'" + near + "'";
  }
  std::vector<std::string> keys;
  std::vector<std::string> sections;
  for (const auto& [sec, names] : read_keys_) {
    if (sec != section && owns(sec)) {
      keys.insert(keys.end(), names.begin(), names.end());
      sections.insert(sections.end(), names.size(), sec);
    }
  }
  const std::string other = nearestWord(key, keys);
  for (std::size_t i = 0; i < keys.size() && !other.empty(); ++i) {
    if (keys[i] == other) {
      return "'" + other + "' in [" + sections[i] + "]";
    }
  }
  return {};
}

void StrictMrptConfig::getAllSections(std::vector<std::string>& sections) const {
  sections = doc_.sectionNames();
  for (const auto& [name, keys] : written_) {
    if (!doc_.hasSection(name)) {
      sections.push_back(name);
    }
  }
}

void StrictMrptConfig::getAllKeys(const std::string& section,
                                  std::vector<std::string>& keys) const {
  keys = doc_.keys(section);
  const auto ws = written_.find(section);
  if (ws == written_.end()) {
    return;
  }
  for (const auto& [name, value] : ws->second) {
    if (doc_.find(section, name) == nullptr) {
      keys.push_back(name);
    }
  }
}

void StrictMrptConfig::clear() {
  // The document is read-only; only values written through this object go.
  written_.clear();
}

void StrictMrptConfig::writeString(const std::string& section, const std::string& name,
                                   const std::string& str) {
  written_[section][name] = str;
}

}  // namespace pmap::config
