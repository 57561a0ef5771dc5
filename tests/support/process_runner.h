// Runs a built program as a child process: its exit status, the signal that
// killed it and its peak memory, with stdout / stderr captured to files (not
// a terminal, as in a log or CI).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace pmap::testing {

struct ProcessResult {
  int exit_code = -1;    ///< -1 when killed by a signal or not started
  int signal = 0;        ///< the signal that ended it, 0 if none
  long max_rss_kib = 0;  ///< peak resident set size (getrusage ru_maxrss)
  std::string out;       ///< what it wrote on stdout
  std::string err;       ///< what it wrote on stderr
};

/// Runs `argv` (argv[0] is the program's path) in `dir` (empty: the current
/// directory) and waits for it.
ProcessResult runProcess(const std::vector<std::string>& argv,
                         const std::filesystem::path& dir = {});

/// A built program of this project (PMAP_BINARY_DIR/bin/<name>).
std::filesystem::path programPath(const std::string& name);

}  // namespace pmap::testing
