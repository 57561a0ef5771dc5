#include "pmap/common/progress.h"

#include <unistd.h>

#include <cstdio>

namespace pmap {

ProgressLine::ProgressLine(std::string label, bool enabled)
    : label_(std::move(label)),
      enabled_(enabled),
      tty_(::isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()),
      last_print_(start_) {}

ProgressLine::~ProgressLine() {
  if (enabled_ && open_line_) {
    std::fputc('\n', stderr);
  }
}

void ProgressLine::update(std::uint64_t done, std::uint64_t total, const std::string& detail) {
  if (!enabled_) {
    return;
  }
  const auto now = std::chrono::steady_clock::now();
  const double since_last = std::chrono::duration<double>(now - last_print_).count();
  if (since_last < (tty_ ? 0.2 : 5.0)) {
    return;
  }
  last_print_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  char buf[160];
  if (total > 0) {
    std::snprintf(buf, sizeof buf, "%s: %llu/%llu (%.0f%%) %.1f s", label_.c_str(),
                  static_cast<unsigned long long>(done), static_cast<unsigned long long>(total),
                  100.0 * static_cast<double>(done) / static_cast<double>(total), elapsed);
  } else {
    std::snprintf(buf, sizeof buf, "%s: %llu %.1f s", label_.c_str(),
                  static_cast<unsigned long long>(done), elapsed);
  }
  print(detail.empty() ? std::string(buf) : std::string(buf) + "  " + detail);
}

void ProgressLine::finish(const std::string& detail) {
  if (!enabled_) {
    return;
  }
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  char buf[160];
  std::snprintf(buf, sizeof buf, "%s: done in %.1f s", label_.c_str(), elapsed);
  print(detail.empty() ? std::string(buf) : std::string(buf) + "  " + detail);
  if (tty_ && open_line_) {
    std::fputc('\n', stderr);
  }
  open_line_ = false;
}

void ProgressLine::print(const std::string& line) {
  if (tty_) {
    std::fprintf(stderr, "\r%-*s", static_cast<int>(last_line_.size()), line.c_str());
    open_line_ = true;
  } else {
    std::fprintf(stderr, "%s\n", line.c_str());
  }
  std::fflush(stderr);
  last_line_ = line;
}

}  // namespace pmap
