// Strict parsing of the rows of the mapper's CSV files (surfaces.csv,
// textures.csv): every field checked, errors name file, line and column.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pmap::eval {

/// Splits on commas, keeping empty fields (so "1,,2" has 3 fields).
std::vector<std::string> splitCsv(const std::string& line);

class RowParser {
 public:
  /// `where` prefixes every error ("file:line: ").
  RowParser(const std::vector<std::string>& fields, std::string where)
      : fields_(fields), where_(std::move(where)) {}

  /// Field k as a finite number; InputError otherwise.
  double number(std::size_t k) const;
  /// Field k as an integer >= 0 (`name` names it in the error).
  std::int64_t count(std::size_t k, const char* name) const;
  [[noreturn]] void fail(const std::string& what) const;

 private:
  const std::vector<std::string>& fields_;
  std::string where_;
};

}  // namespace pmap::eval
