// The indoor-sim command line as a testable class (apps/indoor-sim/main.cpp is
// a thin shell over it):
//   indoor-sim [--world FILE] [--seed N] [--sigma METRES] [--format obs|sf]
//              [--duration SECONDS] [--no-cameras] [--quiet] --out PREFIX
// A world file with an "octomap" block drives the robot through that tree's
// occupied voxels (doc/simulator.md, "Voxel worlds").
// Exit codes: 0 ok, 1 usage or configuration error, 2 input error (a voxel
// world's tree missing, damaged, empty or too large), 4 output
// error (pmap::Error::exitCode()); SIGINT, SIGTERM, SIGHUP during the run:
// pmap::Interrupted (exitCode() 128 + signo) after the temporaries are removed.
#pragma once

#include <string>
#include <vector>

#include "pmap/sim/simulator.h"

namespace pmap::sim {

class IndoorSimApp {
 public:
  /// Parses the command line. Returns false if there is nothing left to do
  /// (--help or --version were printed). Throws ConfigError on usage errors.
  bool initialize(int argc, const char* const* argv);
  bool initialize(const std::vector<std::string>& args);  ///< args[0] is the program name

  /// Runs the simulation and prints a summary on stderr; throws pmap::Error.
  /// While the outputs are written, SIGINT / SIGTERM / SIGHUP stop the run
  /// cleanly (pmap::InterruptGuard): it throws pmap::Interrupted.
  SimulationSummary run();

  const SimulatorOptions& options() const { return options_; }

 private:
  SimulatorOptions options_;
};

/// Where indoor-sim looks for config/worlds/default.json, in order: the
/// source tree it was built from, the install prefix's share directory, and
/// ../share/planar_mapper/worlds next to the running executable.
std::vector<std::string> defaultWorldCandidates();
/// The first existing candidate; ConfigError listing them all otherwise.
std::string findDefaultWorld();

}  // namespace pmap::sim
