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

/// A program started without waiting for it (to signal it, or to run two at
/// once): stdout to /dev/null, stderr to a file, SIGINT / SIGTERM / SIGHUP at
/// their default action (a test runner may ignore them).
struct ChildProcess {
  int pid = -1;
  std::filesystem::path err_file;
  /// Waits for its end: exit_code, signal and err filled in.
  ProcessResult wait() const;
  /// What it wrote on stderr so far.
  std::string err() const;
};

/// Starts `argv` (argv[0] is the program's path). `file_size_limit_bytes` > 0
/// limits the size of every file it writes (RLIMIT_FSIZE, SIGXFSZ ignored):
/// a write beyond it fails with EFBIG, as on a full disk.
ChildProcess startProcess(const std::vector<std::string>& argv,
                          const std::filesystem::path& err_file,
                          long long file_size_limit_bytes = 0);

/// A built program of this project (PMAP_BINARY_DIR/bin/<name>).
std::filesystem::path programPath(const std::string& name);

}  // namespace pmap::testing
