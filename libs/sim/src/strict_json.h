// Strict reading of JSON world files (private to the simulator library):
// every key a reader looks at is registered, finish() rejects the others with
// the nearest known key as a suggestion; wrong types, out-of-range values,
// missing required keys and duplicate keys are ConfigErrors naming the file
// and the JSON path ("corridors[0].doors[2].width_m").
#pragma once

#include <Eigen/Core>
#include <array>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace pmap::sim::detail {

/// A closed or half-open interval of accepted values.
struct Range {
  double lo;
  double hi;
  bool lo_open = false;
  bool hi_open = false;
  bool contains(double v) const;
  std::string describe() const;
};
/// (0, hi]
inline Range positive(double hi) {
  return Range{0.0, hi, true, false};
}
/// [lo, hi]
inline Range closed(double lo, double hi) {
  return Range{lo, hi, false, false};
}

/// Parses `text`; syntax errors and duplicate keys are ConfigErrors naming `file`.
nlohmann::json parseStrictJson(const std::string& text, const std::string& file);

class JsonReader {
 public:
  /// `value` must be an object (else ConfigError); it must outlive the reader.
  JsonReader(const nlohmann::json& value, std::string file, std::string path);

  bool has(const std::string& key);
  double number(const std::string& key, double def, const Range& range);
  double requiredNumber(const std::string& key, const Range& range);
  int integer(const std::string& key, int def, int lo, int hi);
  bool boolean(const std::string& key, bool def);
  std::string string(const std::string& key, const std::string& def);
  /// One of `allowed`; an unknown value gets a suggestion.
  std::string choice(const std::string& key, const std::string& def,
                     const std::vector<std::string>& allowed, bool required = false);
  /// [x, y] (required).
  Eigen::Vector2d point2(const std::string& key);
  /// [x, y, z] (required).
  Eigen::Vector3d point3(const std::string& key);
  /// [a, b, c] with a default.
  std::array<double, 3> triple(const std::string& key, const std::array<double, 3>& def);
  /// [lo, hi] with a default: both in `range`, lo <= hi.
  std::array<double, 2> interval(const std::string& key, const std::array<double, 2>& def,
                                 const Range& range);
  /// [a, b, c, d, e] with a default, each in `range`.
  std::array<double, 5> quintuple(const std::string& key, const std::array<double, 5>& def,
                                  const Range& range);
  /// A required list of at least `min_count` [x, y] points.
  std::vector<Eigen::Vector2d> points2(const std::string& key, std::size_t min_count);
  /// A required list of exactly `count` [x, y, z] points.
  std::vector<Eigen::Vector3d> points3(const std::string& key, std::size_t count);
  /// A nested object (an empty one if absent).
  JsonReader object(const std::string& key);
  /// An optional array of objects.
  std::vector<JsonReader> objects(const std::string& key);

  /// Rejects keys nobody asked for.
  void finish() const;

  /// "corridors[0].width_m" (or "width_m" at the top level).
  std::string pathOf(const std::string& key) const;
  const std::string& path() const { return path_; }
  const std::string& file() const { return file_; }
  /// Throws ConfigError "<file>: <path.key>: <message>".
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;
  /// "missing required key", naming a present key that looks like a typo of it.
  [[noreturn]] void failMissing(const std::string& key) const;

 private:
  const nlohmann::json* find(const std::string& key);
  double toNumber(const std::string& key, const nlohmann::json& v) const;
  Eigen::VectorXd fixedArray(const std::string& key, const nlohmann::json& v, int n) const;

  const nlohmann::json* value_;
  std::string file_;
  std::string path_;
  std::vector<std::string> known_;
};

}  // namespace pmap::sim::detail
