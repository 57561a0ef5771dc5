// planar-mapper as a class (as MRPT's ICP_SLAM_App): main() is a thin shell,
// tests drive the whole program in-process.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "pmap/mapper/mapper_args.h"
#include "pmap/mapper/mapper_config.h"

namespace pmap::mapper {

class PlanarMapperApp {
 public:
  /// Parses the command line and loads the configuration. Returns false when
  /// there is nothing to run (--help). Throws pmap::Error.
  bool initialize(int argc, const char* const* argv);

  /// Runs the mapping and writes the outputs: into a staging folder beside
  /// --out, swapped in as a whole at the end (staged_outputs.h), under an
  /// InterruptGuard. Throws pmap::Error; pmap::Interrupted on SIGINT,
  /// SIGTERM or SIGHUP (the staging folder removed, --out untouched).
  void run();

  const MapperArgs& args() const { return *args_; }

 private:
  std::vector<std::string> command_;  ///< argv, for the manifest
  std::optional<MapperArgs> args_;
  std::optional<MapperConfig> config_;
};

/// main() of planar-mapper: runs the app, prints one-line errors as
/// "planar-mapper: error: ..." and returns the documented exit code. When
/// interrupted it prints one line and ends by the same signal
/// (reraiseWithDefaultAction).
int planarMapperMain(int argc, const char* const* argv);

}  // namespace pmap::mapper
