// Runs an app's main() in-process with a vector of arguments.
#pragma once

#include <string>
#include <vector>

namespace pmap::testing {

using MainFunction = int (*)(int, const char* const*);

/// Calls `main_fn` with argv = {program, args...} and returns its exit code.
inline int runMain(MainFunction main_fn, const std::string& program,
                   const std::vector<std::string>& args) {
  std::vector<const char*> argv = {program.c_str()};
  for (const auto& a : args) {
    argv.push_back(a.c_str());
  }
  return main_fn(static_cast<int>(argv.size()), argv.data());
}

}  // namespace pmap::testing
