// A progress line on stderr for long runs: rewritten in place on a terminal,
// one line every few seconds otherwise (logs, CI).
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>

namespace pmap {

struct ProgressOptions {
  bool enabled = true;       ///< false makes every call a no-op
  double min_seconds = 0.0;  ///< a stage that ends sooner prints nothing at all
  /// Repeat the last state every few seconds from a thread, for stages that
  /// cannot report their own progress (a Ceres solve, writing files).
  bool heartbeat = false;
};

class ProgressLine {
 public:
  /// `label` prefixes each line.
  explicit ProgressLine(std::string label, ProgressOptions options = {});
  /// Shorthand for ProgressOptions{enabled}.
  ProgressLine(std::string label, bool enabled);
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  /// Reports `done` units of work (of `total`, 0 if unknown) and a free-form
  /// `detail`. Throttled: prints at most every 0.2 s on a terminal, every
  /// 3 s otherwise, never before `min_seconds`.
  void update(std::uint64_t done, std::uint64_t total, const std::string& detail = {});

  /// Prints the final line ("done in X s", unless the stage ended within
  /// `min_seconds` having printed nothing) and ends it with a newline.
  void finish(const std::string& detail = {});

 private:
  void updateLocked(std::uint64_t done, std::uint64_t total, const std::string& detail,
                    bool forced);
  void print(const std::string& line);
  void stopHeartbeat();
  double elapsed() const;

  std::string label_;
  ProgressOptions options_;
  bool tty_;
  bool open_line_ = false;
  bool printed_ = false;
  bool finished_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_print_;
  std::string last_line_;
  std::uint64_t done_ = 0;
  std::uint64_t total_ = 0;
  std::string detail_;
  std::mutex mutex_;
  std::condition_variable stop_;
  bool stopping_ = false;
  std::thread heartbeat_;
};

}  // namespace pmap
