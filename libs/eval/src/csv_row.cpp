#include "pmap/eval/csv_row.h"

#include "pmap/common/error.h"
#include "pmap/common/text.h"

namespace pmap::eval {

std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> fields(1);
  for (const char ch : line) {
    if (ch == ',') {
      fields.emplace_back();
    } else {
      fields.back() += ch;
    }
  }
  return fields;
}

double RowParser::number(std::size_t k) const {
  const auto v = parseDouble(fields_[k]);
  if (!v) {
    fail("column " + std::to_string(k + 1) + " '" + trim(fields_[k]) + "' is not a finite number");
  }
  return *v;
}

std::int64_t RowParser::count(std::size_t k, const char* name) const {
  const auto v = parseInt(fields_[k]);
  if (!v || *v < 0) {
    fail(std::string(name) + " '" + trim(fields_[k]) + "' is not an integer >= 0");
  }
  return *v;
}

void RowParser::fail(const std::string& what) const {
  throw InputError(where_ + what);
}

}  // namespace pmap::eval
