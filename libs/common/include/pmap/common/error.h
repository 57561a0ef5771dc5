// Error policy of the project (see doc/errors.md):
//  - libraries throw the typed exceptions below for configuration, input and
//    output problems; each maps to one documented exit code of the apps;
//  - expected data outcomes (a degenerate cluster, an empty map) are returned
//    as status values, never thrown;
//  - internal invariants are assert()ed;
//  - nothing under libs/ calls exit().
#pragma once

#include <stdexcept>
#include <string>

namespace pmap {

/// Exit codes of every app (doc/errors.md).
enum class ExitCode : int {
  kOk = 0,
  kConfig = 1,      ///< usage or configuration error
  kInput = 2,       ///< input data error (rawlog, poses, cloud, ground truth)
  kProcessing = 3,  ///< processing failure
  kOutput = 4,      ///< output write error
};

/// Base of all project errors. what() is one line naming the file and, where
/// it applies, record index, byte offset, section and key.
class Error : public std::runtime_error {
 public:
  Error(ExitCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ExitCode code() const { return code_; }
  int exitCode() const { return static_cast<int>(code_); }

 private:
  ExitCode code_;
};

/// Bad command line or ini (exit 1).
class ConfigError : public Error {
 public:
  explicit ConfigError(const std::string& message) : Error(ExitCode::kConfig, message) {}
};

/// Unusable input data: rawlog, poses file, point cloud, ground truth (exit 2).
class InputError : public Error {
 public:
  explicit InputError(const std::string& message) : Error(ExitCode::kInput, message) {}
};

/// A processing stage failed (exit 3).
class ProcessingError : public Error {
 public:
  explicit ProcessingError(const std::string& message) : Error(ExitCode::kProcessing, message) {}
};

/// An output could not be written (exit 4).
class OutputError : public Error {
 public:
  explicit OutputError(const std::string& message) : Error(ExitCode::kOutput, message) {}
};

}  // namespace pmap
