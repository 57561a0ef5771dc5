// A progress line on stderr for long runs: rewritten in place on a terminal,
// one line every few seconds otherwise (logs, CI).
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace pmap {

class ProgressLine {
 public:
  /// `label` prefixes each line; `enabled` false makes every call a no-op.
  explicit ProgressLine(std::string label, bool enabled = true);
  ~ProgressLine();

  /// Reports `done` units of work (of `total`, 0 if unknown) and a free-form
  /// `detail`. Throttled: prints at most every 0.2 s on a terminal, 5 s otherwise.
  void update(std::uint64_t done, std::uint64_t total, const std::string& detail = {});

  /// Prints the final line (always) and ends it with a newline.
  void finish(const std::string& detail = {});

 private:
  void print(const std::string& line);

  std::string label_;
  bool enabled_;
  bool tty_;
  bool open_line_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_print_;
  std::string last_line_;
};

}  // namespace pmap
