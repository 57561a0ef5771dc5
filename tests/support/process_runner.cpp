#include "process_runner.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "rawlog_fixtures.h"

namespace pmap::testing {
namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Waits for `pid`: its exit code or signal and peak RSS. False if it could
// not be waited for (pid < 0: the fork failed).
bool waitFor(pid_t pid, ProcessResult& r) {
  int status = 0;
  rusage usage{};
  if (pid < 0 || ::wait4(pid, &status, 0, &usage) != pid) {
    return false;
  }
  r.max_rss_kib = usage.ru_maxrss;
  if (WIFEXITED(status)) {
    r.exit_code = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    r.signal = WTERMSIG(status);
  }
  return true;
}

// execv's argument vector: pointers into `argv`, null-terminated.
std::vector<char*> execArgs(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const std::string& a : argv) {
    args.push_back(const_cast<char*>(a.c_str()));
  }
  args.push_back(nullptr);
  return args;
}

}  // namespace

fs::path programPath(const std::string& name) {
  return fs::path(PMAP_BINARY_DIR) / "bin" / name;
}

ProcessResult runProcess(const std::vector<std::string>& argv, const fs::path& dir) {
  const fs::path tmp = freshTestDir("process_" + std::to_string(::getpid()));
  const fs::path out = tmp / "stdout", err = tmp / "stderr";
  std::vector<char*> args = execArgs(argv);
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int o = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (o < 0 || e < 0 || ::dup2(o, 1) < 0 || ::dup2(e, 2) < 0 ||
        (!dir.empty() && ::chdir(dir.c_str()) != 0)) {
      ::_exit(126);
    }
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  ProcessResult r;
  if (waitFor(pid, r)) {
    r.out = slurp(out);
    r.err = slurp(err);
  }
  return r;
}

ChildProcess startProcess(const std::vector<std::string>& argv, const fs::path& err_file,
                          long long file_size_limit_bytes) {
  std::vector<char*> args = execArgs(argv);
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int e = ::open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int o = ::open("/dev/null", O_WRONLY);
    if (o < 0 || e < 0 || ::dup2(o, 1) < 0 || ::dup2(e, 2) < 0) {
      ::_exit(126);
    }
    for (const int s : {SIGINT, SIGTERM, SIGHUP}) {
      ::signal(s, SIG_DFL);
    }
    if (file_size_limit_bytes > 0) {
      const auto limit = static_cast<rlim_t>(file_size_limit_bytes);
      const rlimit r{limit, limit};
      ::setrlimit(RLIMIT_FSIZE, &r);
      ::signal(SIGXFSZ, SIG_IGN);  // the write fails with EFBIG instead
    }
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  return {pid, err_file};
}

ProcessResult ChildProcess::wait() const {
  ProcessResult r;
  if (waitFor(pid, r)) {
    r.err = err();
  }
  return r;
}

std::string ChildProcess::err() const {
  return slurp(err_file);
}

}  // namespace pmap::testing
