#include "pmap/config/section_reader.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "pmap/common/error.h"
#include "pmap/common/text.h"

namespace pmap::config {

namespace {

const char* const kBoolSpellings = "expected true/false, yes/no, on/off or 1/0";

/// Shortest "%.*g" text that parses back to exactly `v`.
std::string formatDouble(double v) {
  char buf[64];
  if (v == std::trunc(v) && std::fabs(v) < 1e15) {
    std::snprintf(buf, sizeof(buf), "%.0f", v);  // 80 rather than 8e+01
    return buf;
  }
  for (int precision = 1; precision <= 17; ++precision) {
    std::snprintf(buf, sizeof(buf), "%.*g", precision, v);
    if (std::strtod(buf, nullptr) == v) {
      break;
    }
  }
  return buf;
}

bool looksLikeInteger(const std::string& s) {
  const std::string t = trim(s);
  std::size_t i = (!t.empty() && (t[0] == '-' || t[0] == '+')) ? 1 : 0;
  if (i >= t.size()) {
    return false;
  }
  for (; i < t.size(); ++i) {
    if (t[i] < '0' || t[i] > '9') {
      return false;
    }
  }
  return true;
}

/// Why `text` is not a valid integer of the type named `type`.
std::string integerError(const std::string& text, const std::string& type) {
  if (looksLikeInteger(text)) {
    return "out of range for " + type;
  }
  return parseDouble(text) ? "not an integer" : "not a number";
}

std::string joinList(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) {
    out += (i ? "," : "") + items[i];
  }
  return out;
}

std::vector<std::string> splitList(const std::string& value) {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (true) {
    const auto comma = value.find(',', start);
    items.push_back(trim(value.substr(start, comma - start)));
    if (comma == std::string::npos) {
      return items;
    }
    start = comma + 1;
  }
}

}  // namespace

SectionReader::SectionReader(const IniDocument& doc, std::string section,
                             EffectiveConfig* effective, Presence presence)
    : doc_(doc), section_(std::move(section)), effective_(effective) {
  present_ = doc_.hasSection(section_);
  if (!present_ && presence == Presence::kRequired) {
    std::string msg = doc_.origin() + ": missing section [" + section_ + "]";
    const std::string near = nearestWord(section_, doc_.sectionNames());
    if (!near.empty()) {
      msg += " (did you mean [" + near + "]?)";
    }
    throw ConfigError(msg);
  }
}

const IniValue* SectionReader::lookup(const std::string& key) {
  known_keys_.push_back(key);
  return doc_.find(section_, key);
}

void SectionReader::record(const std::string& key, const std::string& value, bool from_default) {
  recorded_[key] = value;
  if (effective_ != nullptr) {
    effective_->record(section_, key, value, from_default);
  }
}

void SectionReader::parseError(const std::string& key, const IniValue& v, const std::string& what) {
  errors_.push_back(v.file + ":" + std::to_string(v.line) + ": [" + section_ + "] " + key + " = '" +
                    v.value + "': " + what);
}

void SectionReader::read(const std::string& key, double& value) {
  if (const IniValue* v = lookup(key)) {
    const auto parsed = parseDouble(v->value);
    if (!parsed) {
      return parseError(key, *v, "not a number");
    }
    value = *parsed;
    record(key, v->value, false);
  } else {
    record(key, formatDouble(value), true);
  }
}

void SectionReader::read(const std::string& key, std::int64_t& value) {
  if (const IniValue* v = lookup(key)) {
    const auto parsed = parseInt(v->value);
    if (!parsed) {
      return parseError(key, *v, integerError(v->value, "a 64-bit integer"));
    }
    value = *parsed;
    record(key, v->value, false);
  } else {
    record(key, std::to_string(value), true);
  }
}

void SectionReader::read(const std::string& key, int& value) {
  if (const IniValue* v = lookup(key)) {
    const auto parsed = parseInt(v->value);
    if (!parsed || *parsed < std::numeric_limits<int>::min() ||
        *parsed > std::numeric_limits<int>::max()) {
      return parseError(key, *v, integerError(v->value, "int"));
    }
    value = static_cast<int>(*parsed);
    record(key, v->value, false);
  } else {
    record(key, std::to_string(value), true);
  }
}

void SectionReader::read(const std::string& key, bool& value) {
  if (const IniValue* v = lookup(key)) {
    const auto parsed = parseBool(v->value);
    if (!parsed) {
      return parseError(key, *v, std::string("not a boolean (") + kBoolSpellings + ")");
    }
    value = *parsed;
    record(key, v->value, false);
  } else {
    record(key, value ? "true" : "false", true);
  }
}

void SectionReader::read(const std::string& key, std::string& value) {
  if (const IniValue* v = lookup(key)) {
    value = v->value;
    record(key, v->value, false);
  } else {
    record(key, value, true);
  }
}

void SectionReader::readNumberOrAuto(const std::string& key, double& value, bool& is_auto) {
  const IniValue* v = lookup(key);
  if (v == nullptr) {
    record(key, is_auto ? "auto" : formatDouble(value), true);
    return;
  }
  if (toLower(trim(v->value)) == "auto") {
    is_auto = true;
    record(key, "auto", false);
    return;
  }
  const auto parsed = parseDouble(v->value);
  if (!parsed) {
    return parseError(key, *v, "not a number or auto");
  }
  value = *parsed;
  is_auto = false;
  record(key, v->value, false);
}

void SectionReader::read(const std::string& key, std::vector<std::string>& value) {
  if (const IniValue* v = lookup(key)) {
    value = splitList(v->value);
    record(key, v->value, false);
  } else {
    record(key, joinList(value), true);
  }
}

void SectionReader::fail(const std::string& key, const std::string& rule) const {
  if (const IniValue* v = doc_.find(section_, key)) {
    throw ConfigError(v->file + ":" + std::to_string(v->line) + ": [" + section_ + "] " + key +
                      " = " + v->value + ": " + rule);
  }
  const auto rec = recorded_.find(key);
  const std::string shown = rec == recorded_.end() ? key : key + " = " + rec->second;
  throw ConfigError(doc_.origin() + ": [" + section_ + "] " + shown + " (default): " + rule);
}

void SectionReader::finish() const {
  std::vector<std::string> errors = errors_;
  for (const auto& key : doc_.keys(section_)) {
    bool known = false;
    for (const auto& k : known_keys_) {
      known = known || k == key;
    }
    if (known) {
      continue;
    }
    std::string msg =
        doc_.location(section_, key) + ": [" + section_ + "] unknown key '" + key + "'";
    const std::string near = nearestWord(key, known_keys_);
    if (!near.empty()) {
      msg += " (did you mean '" + near + "'?)";
    }
    errors.push_back(msg);
  }
  if (!errors.empty()) {
    throw ConfigError(joinLines(errors));
  }
}

void throwInvalidOptions(const IniDocument& doc, const std::string& section,
                         const std::string& why) {
  throw ConfigError(doc.origin() + ": [" + section + "] " + why);
}

}  // namespace pmap::config
