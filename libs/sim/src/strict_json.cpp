#include "strict_json.h"

#include <cmath>
#include <set>
#include <sstream>

#include "pmap/common/error.h"
#include "pmap/common/text.h"

namespace pmap::sim::detail {
namespace {

const nlohmann::json& emptyObject() {
  static const nlohmann::json empty = nlohmann::json::object();
  return empty;
}

std::string typeName(const nlohmann::json& v) {
  if (v.is_number()) {
    return "a number";
  }
  if (v.is_string()) {
    return "a string";
  }
  if (v.is_boolean()) {
    return "a boolean";
  }
  if (v.is_null()) {
    return "null";
  }
  return v.is_array() ? "an array" : "an object";
}

std::string formatNumber(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

bool Range::contains(double v) const {
  if (!std::isfinite(v)) {
    return false;
  }
  const bool lo_ok = lo_open ? v > lo : v >= lo;
  const bool hi_ok = hi_open ? v < hi : v <= hi;
  return lo_ok && hi_ok;
}

std::string Range::describe() const {
  return std::string(lo_open ? "(" : "[") + formatNumber(lo) + ", " + formatNumber(hi) +
         (hi_open ? ")" : "]");
}

nlohmann::json parseStrictJson(const std::string& text, const std::string& file) {
  std::vector<std::set<std::string>> open_objects;
  auto callback = [&](int /*depth*/, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    using E = nlohmann::json::parse_event_t;
    if (event == E::object_start) {
      open_objects.emplace_back();
    } else if (event == E::object_end && !open_objects.empty()) {
      open_objects.pop_back();
    } else if (event == E::key && !open_objects.empty()) {
      const std::string key = parsed.get<std::string>();
      if (!open_objects.back().insert(key).second) {
        throw ConfigError(file + ": duplicate key \"" + key + "\"");
      }
    }
    return true;
  };
  try {
    return nlohmann::json::parse(text, callback);
  } catch (const nlohmann::json::exception& e) {
    throw ConfigError(file + ": invalid JSON: " + e.what());
  }
}

JsonReader::JsonReader(const nlohmann::json& value, std::string file, std::string path)
    : value_(&value), file_(std::move(file)), path_(std::move(path)) {
  if (!value.is_object()) {
    throw ConfigError(file_ + ": " + (path_.empty() ? std::string("top level") : path_) +
                      ": expected an object, got " + typeName(value));
  }
}

std::string JsonReader::pathOf(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

void JsonReader::fail(const std::string& key, const std::string& message) const {
  throw ConfigError(file_ + ": " + pathOf(key) + ": " + message);
}

void JsonReader::failMissing(const std::string& key) const {
  std::vector<std::string> present;
  for (auto it = value_->begin(); it != value_->end(); ++it) {
    present.push_back(it.key());
  }
  const std::string near = nearestWord(key, present);
  fail(key, "missing required key" +
                (near.empty() ? std::string() : " (found \"" + near + "\": a typo?)"));
}

const nlohmann::json* JsonReader::find(const std::string& key) {
  known_.push_back(key);
  const auto it = value_->find(key);
  return it == value_->end() ? nullptr : &*it;
}

bool JsonReader::has(const std::string& key) {
  return find(key) != nullptr;
}

double JsonReader::toNumber(const std::string& key, const nlohmann::json& v) const {
  if (!v.is_number()) {
    fail(key, "expected a number, got " + typeName(v));
  }
  return v.get<double>();
}

double JsonReader::number(const std::string& key, double def, const Range& range) {
  const nlohmann::json* v = find(key);
  const double x = v == nullptr ? def : toNumber(key, *v);
  if (!range.contains(x)) {
    fail(key, formatNumber(x) + " is out of range " + range.describe());
  }
  return x;
}

double JsonReader::requiredNumber(const std::string& key, const Range& range) {
  if (value_->find(key) == value_->end()) {
    known_.push_back(key);
    failMissing(key);
  }
  return number(key, 0.0, range);
}

int JsonReader::integer(const std::string& key, int def, int lo, int hi) {
  const nlohmann::json* v = find(key);
  if (v != nullptr && !v->is_number_integer()) {
    fail(key, "expected an integer, got " + typeName(*v));
  }
  const long long x = v == nullptr ? def : v->get<long long>();
  if (x < lo || x > hi) {
    fail(key, std::to_string(x) + " is out of range [" + std::to_string(lo) + ", " +
                  std::to_string(hi) + "]");
  }
  return static_cast<int>(x);
}

bool JsonReader::boolean(const std::string& key, bool def) {
  const nlohmann::json* v = find(key);
  if (v == nullptr) {
    return def;
  }
  if (!v->is_boolean()) {
    fail(key, "expected true or false, got " + typeName(*v));
  }
  return v->get<bool>();
}

std::string JsonReader::string(const std::string& key, const std::string& def) {
  const nlohmann::json* v = find(key);
  if (v == nullptr) {
    return def;
  }
  if (!v->is_string()) {
    fail(key, "expected a string, got " + typeName(*v));
  }
  return v->get<std::string>();
}

std::string JsonReader::choice(const std::string& key, const std::string& def,
                               const std::vector<std::string>& allowed, bool required) {
  if (required && value_->find(key) == value_->end()) {
    known_.push_back(key);
    failMissing(key);
  }
  const std::string s = string(key, def);
  for (const std::string& a : allowed) {
    if (a == s) {
      return s;
    }
  }
  std::string list;
  for (const std::string& a : allowed) {
    list += (list.empty() ? "" : ", ") + a;
  }
  const std::string near = nearestWord(s, allowed);
  fail(key, "\"" + s + "\" is not one of " + list +
                (near.empty() ? std::string() : " (did you mean \"" + near + "\"?)"));
}

Eigen::VectorXd JsonReader::fixedArray(const std::string& key, const nlohmann::json& v,
                                       int n) const {
  if (!v.is_array() || static_cast<int>(v.size()) != n) {
    fail(key, "expected an array of " + std::to_string(n) + " numbers, got " + typeName(v));
  }
  Eigen::VectorXd out(n);
  for (int i = 0; i < n; ++i) {
    const nlohmann::json& e = v[static_cast<std::size_t>(i)];
    if (!e.is_number() || !std::isfinite(e.get<double>())) {
      fail(key, "element " + std::to_string(i) + " is not a finite number");
    }
    out[i] = e.get<double>();
  }
  return out;
}

Eigen::Vector2d JsonReader::point2(const std::string& key) {
  const nlohmann::json* v = find(key);
  if (v == nullptr) {
    failMissing(key);
  }
  const Eigen::VectorXd p = fixedArray(key, *v, 2);
  return Eigen::Vector2d(p[0], p[1]);
}

Eigen::Vector3d JsonReader::point3(const std::string& key) {
  const nlohmann::json* v = find(key);
  if (v == nullptr) {
    failMissing(key);
  }
  const Eigen::VectorXd p = fixedArray(key, *v, 3);
  return Eigen::Vector3d(p[0], p[1], p[2]);
}

std::array<double, 3> JsonReader::triple(const std::string& key, const std::array<double, 3>& def) {
  const nlohmann::json* v = find(key);
  if (v == nullptr) {
    return def;
  }
  const Eigen::VectorXd p = fixedArray(key, *v, 3);
  return {p[0], p[1], p[2]};
}

std::array<double, 2> JsonReader::interval(const std::string& key, const std::array<double, 2>& def,
                                           const Range& range) {
  const nlohmann::json* v = find(key);
  if (v == nullptr) {
    return def;
  }
  const Eigen::VectorXd p = fixedArray(key, *v, 2);
  for (int i = 0; i < 2; ++i) {
    if (!range.contains(p[i])) {
      fail(key, formatNumber(p[i]) + " is out of range " + range.describe());
    }
  }
  if (p[0] > p[1]) {
    fail(key, "[" + formatNumber(p[0]) + ", " + formatNumber(p[1]) +
                  "]: the lower bound exceeds the upper bound");
  }
  return {p[0], p[1]};
}

std::array<double, 5> JsonReader::quintuple(const std::string& key,
                                            const std::array<double, 5>& def, const Range& range) {
  const nlohmann::json* v = find(key);
  if (v == nullptr) {
    return def;
  }
  const Eigen::VectorXd p = fixedArray(key, *v, 5);
  std::array<double, 5> out{};
  for (int i = 0; i < 5; ++i) {
    if (!range.contains(p[i])) {
      fail(key, "element " + std::to_string(i) + ": " + formatNumber(p[i]) + " is out of range " +
                    range.describe());
    }
    out[static_cast<std::size_t>(i)] = p[i];
  }
  return out;
}

std::vector<Eigen::Vector2d> JsonReader::points2(const std::string& key, std::size_t min_count) {
  const nlohmann::json* v = find(key);
  if (v == nullptr) {
    failMissing(key);
  }
  if (!v->is_array() || v->size() < min_count) {
    fail(key, "expected an array of at least " + std::to_string(min_count) + " [x, y] points");
  }
  std::vector<Eigen::Vector2d> out;
  for (std::size_t i = 0; i < v->size(); ++i) {
    const Eigen::VectorXd p = fixedArray(key + "[" + std::to_string(i) + "]", (*v)[i], 2);
    out.emplace_back(p[0], p[1]);
  }
  return out;
}

std::vector<Eigen::Vector3d> JsonReader::points3(const std::string& key, std::size_t count) {
  const nlohmann::json* v = find(key);
  if (v == nullptr) {
    failMissing(key);
  }
  if (!v->is_array() || v->size() != count) {
    fail(key, "expected an array of " + std::to_string(count) + " [x, y, z] points");
  }
  std::vector<Eigen::Vector3d> out;
  for (std::size_t i = 0; i < v->size(); ++i) {
    const Eigen::VectorXd p = fixedArray(key + "[" + std::to_string(i) + "]", (*v)[i], 3);
    out.emplace_back(p[0], p[1], p[2]);
  }
  return out;
}

JsonReader JsonReader::object(const std::string& key) {
  const nlohmann::json* v = find(key);
  return JsonReader(v == nullptr ? emptyObject() : *v, file_, pathOf(key));
}

std::vector<JsonReader> JsonReader::objects(const std::string& key) {
  const nlohmann::json* v = find(key);
  std::vector<JsonReader> out;
  if (v == nullptr) {
    return out;
  }
  if (!v->is_array()) {
    fail(key, "expected an array of objects, got " + typeName(*v));
  }
  for (std::size_t i = 0; i < v->size(); ++i) {
    out.emplace_back((*v)[i], file_, pathOf(key) + "[" + std::to_string(i) + "]");
  }
  return out;
}

void JsonReader::finish() const {
  for (auto it = value_->begin(); it != value_->end(); ++it) {
    bool found = false;
    for (const std::string& k : known_) {
      found = found || k == it.key();
    }
    if (!found) {
      const std::string near = nearestWord(it.key(), known_);
      throw ConfigError(file_ + ": unknown key \"" + pathOf(it.key()) + "\"" +
                        (near.empty() ? std::string() : " (did you mean \"" + near + "\"?)"));
    }
  }
}

}  // namespace pmap::sim::detail
