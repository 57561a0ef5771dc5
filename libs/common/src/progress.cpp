#include "pmap/common/progress.h"

#include <unistd.h>

#include <cstdio>

namespace pmap {
namespace {

double intervalSeconds(bool tty) {
  return tty ? 0.2 : 3.0;
}

}  // namespace

ProgressLine::ProgressLine(std::string label, ProgressOptions options)
    : label_(std::move(label)),
      options_(options),
      tty_(::isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()),
      last_print_(start_) {
  if (options_.enabled && options_.heartbeat) {
    heartbeat_ = std::thread([this] {
      std::unique_lock<std::mutex> lock(mutex_);
      const auto period = std::chrono::duration<double>(tty_ ? 0.5 : 3.0);
      while (!stop_.wait_for(lock, period, [this] { return stopping_; })) {
        updateLocked(done_, total_, detail_, true);
      }
    });
  }
}

ProgressLine::ProgressLine(std::string label, bool enabled)
    : ProgressLine(std::move(label), ProgressOptions{enabled, 0.0, false}) {}

ProgressLine::~ProgressLine() {
  stopHeartbeat();
  if (options_.enabled && open_line_) {
    std::fputc('\n', stderr);
  }
}

void ProgressLine::stopHeartbeat() {
  if (heartbeat_.joinable()) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    stop_.notify_all();
    heartbeat_.join();
  }
}

double ProgressLine::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void ProgressLine::update(std::uint64_t done, std::uint64_t total, const std::string& detail) {
  if (!options_.enabled) {
    return;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  updateLocked(done, total, detail, false);
}

void ProgressLine::updateLocked(std::uint64_t done, std::uint64_t total, const std::string& detail,
                                bool forced) {
  done_ = done;
  total_ = total;
  detail_ = detail;
  const auto now = std::chrono::steady_clock::now();
  const double since_last = std::chrono::duration<double>(now - last_print_).count();
  const double seconds = elapsed();
  if (finished_ || (!forced && since_last < intervalSeconds(tty_)) ||
      seconds < options_.min_seconds) {
    return;
  }
  last_print_ = now;
  char buf[160];
  if (total > 0) {
    std::snprintf(buf, sizeof buf, "%s: %llu/%llu (%.0f%%) %.1f s", label_.c_str(),
                  static_cast<unsigned long long>(done), static_cast<unsigned long long>(total),
                  100.0 * static_cast<double>(done) / static_cast<double>(total), seconds);
  } else if (done > 0) {
    std::snprintf(buf, sizeof buf, "%s: %llu %.1f s", label_.c_str(),
                  static_cast<unsigned long long>(done), seconds);
  } else {
    std::snprintf(buf, sizeof buf, "%s: %.1f s", label_.c_str(), seconds);
  }
  print(detail.empty() ? std::string(buf) : std::string(buf) + "  " + detail);
}

void ProgressLine::finish(const std::string& detail) {
  if (!options_.enabled) {
    return;
  }
  stopHeartbeat();
  std::lock_guard<std::mutex> lock(mutex_);
  const double seconds = elapsed();
  finished_ = true;
  if (!printed_ && seconds < options_.min_seconds) {
    return;
  }
  char buf[160];
  std::snprintf(buf, sizeof buf, "%s: done in %.1f s", label_.c_str(), seconds);
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
  printed_ = true;
}

}  // namespace pmap
