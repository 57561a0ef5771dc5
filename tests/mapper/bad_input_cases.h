// The table of planar-mapper's bad-input cases (doc/robustness.md): each
// row writes its input files into a fresh directory and returns the command
// line; the test runs it and checks the exit code and message.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace pmap::testing {

struct BadInputCase {
  using Setup = std::function<std::vector<std::string>(const std::filesystem::path& dir)>;
  using Check = std::function<void(const std::filesystem::path& dir)>;

  BadInputCase(std::string name_, Setup setup_, int exit_code_, std::string message_,
               Check check_ = {}, bool unprivileged_ = false)
      : name(std::move(name_)),
        setup(std::move(setup_)),
        exit_code(exit_code_),
        message(std::move(message_)),
        check(std::move(check_)),
        unprivileged(unprivileged_) {}

  std::string name;  ///< the test's name (letters, digits, '_')
  Setup setup;       ///< writes the input files into dir, returns the arguments
  int exit_code = 0;
  std::string message;  ///< a fragment of stderr (error or warning)
  Check check;          ///< further checks of the outputs in dir/out (exit 0 rows)
  /// Run in a child without root's powers (file permissions must hold).
  bool unprivileged = false;
};

/// gtest prints a row by its name.
inline void PrintTo(const BadInputCase& c, std::ostream* os) {
  *os << c.name;
}

/// Rows of the three groups, then all of them.
std::vector<BadInputCase> rawlogCases();
std::vector<BadInputCase> configCases();
std::vector<BadInputCase> outputCases();
std::vector<BadInputCase> badInputCases();

}  // namespace pmap::testing
