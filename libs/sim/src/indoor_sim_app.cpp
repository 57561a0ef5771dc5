#include "pmap/sim/indoor_sim_app.h"

#include <iostream>

#include "pmap/common/error.h"
#include "pmap/common/interrupt.h"
#include "pmap/common/text.h"
#include "pmap/config/command_line.h"

namespace pmap::sim {
namespace {

constexpr const char* kDescription =
    "indoor-sim: simulates a robot with a horizontal and a vertical 2D laser, drifting odometry "
    "and two side cameras driving through a synthetic building described by a world file "
    "(config/worlds/*.json), or through the occupied voxels of any OctoMap tree (.bt) that a "
    "world file names in its \"octomap\" block (no cameras then). Writes PREFIX.rawlog (MRPT "
    "rawlog, gzip), PREFIX_Images/ (camera "
    "JPEGs referenced by the rawlog, poster PNGs), PREFIX.gt.json (exact ground truth, "
    "doc/ground-truth.md) and PREFIX.poses.txt (true poses); the four replace an earlier set "
    "together or not at all. Exit codes: 0 ok, 1 usage or configuration error, 2 input error, "
    "4 output error; SIGINT/SIGTERM/SIGHUP remove the temporary files, keep the earlier set "
    "and end the process by that signal (shell status 130/143/129).";

double parseNumberArg(const std::string& name, const std::string& text) {
  const std::optional<double> v = parseDouble(text);
  if (!v) {
    throw ConfigError("usage: --" + name + ": \"" + text + "\" is not a number");
  }
  return *v;
}

}  // namespace

bool IndoorSimApp::initialize(const std::vector<std::string>& args) {
  std::vector<const char*> argv;
  for (const std::string& a : args) {
    argv.push_back(a.c_str());
  }
  return initialize(static_cast<int>(argv.size()), argv.data());
}

bool IndoorSimApp::initialize(int argc, const char* const* argv) {
  TCLAP::CmdLine cmd(kDescription, ' ', "1.0");
  TCLAP::ValueArg<std::string> out("", "out",
                                   "Output prefix: writes PREFIX.rawlog, "
                                   "PREFIX_Images/, PREFIX.gt.json, PREFIX.poses.txt",
                                   true, "", "PREFIX", cmd);
  TCLAP::ValueArg<std::string> world("", "world",
                                     "World file (default: "
                                     "config/worlds/default.json)",
                                     false, "", "FILE", cmd);
  TCLAP::ValueArg<std::string> seed("", "seed",
                                    "Random seed, a non-negative integer "
                                    "(default 1)",
                                    false, "1", "N", cmd);
  TCLAP::ValueArg<std::string> sigma("", "sigma",
                                     "Laser range noise sigma in metres (default: "
                                     "the world's noise.range_sigma_m, 0.02)",
                                     false, "", "METRES", cmd);
  std::vector<std::string> formats = {"obs", "sf"};
  TCLAP::ValuesConstraint<std::string> format_values(formats);
  TCLAP::ValueArg<std::string> format("", "format",
                                      "Rawlog format: obs = observations only, "
                                      "sf = actions + sensory frames (default obs)",
                                      false, "obs", &format_values, cmd);
  TCLAP::ValueArg<std::string> duration("", "duration",
                                        "Stop after this many simulated "
                                        "seconds (default: the whole path)",
                                        false, "", "SECONDS", cmd);
  TCLAP::SwitchArg no_cameras("", "no-cameras", "Do not render camera images", cmd, false);
  TCLAP::SwitchArg quiet("", "quiet", "No progress line on stderr", cmd, false);
  if (!config::parseCommandLine(cmd, argc, argv)) {
    return false;  // --help or --version printed
  }
  options_.out_prefix = out.getValue();
  options_.world_file = world.isSet() ? world.getValue() : findDefaultWorld();
  const std::optional<std::int64_t> seed_value = parseInt(seed.getValue());
  if (!seed_value || *seed_value < 0) {
    throw ConfigError("usage: --seed: \"" + seed.getValue() + "\" is not a non-negative integer");
  }
  options_.seed = static_cast<std::uint64_t>(*seed_value);
  if (sigma.isSet()) {
    options_.sigma_m = parseNumberArg("sigma", sigma.getValue());
  }
  if (duration.isSet()) {
    options_.duration_s = parseNumberArg("duration", duration.getValue());
  }
  options_.format = *parseRawlogFormat(format.getValue());
  options_.cameras = !no_cameras.getValue();
  options_.progress = !quiet.getValue();
  std::string why;
  if (!options_.validate(&why)) {
    throw ConfigError("usage: " + why);
  }
  return true;
}

SimulationSummary IndoorSimApp::run() {
  Simulator simulator(options_);  // before the guard: nothing written yet, a signal may kill
  SimulationSummary s;
  {
    InterruptGuard guard;
    s = simulator.run();
  }
  std::cerr << "indoor-sim: " << simulator.world().name << ": " << s.cycles << " cycles ("
            << s.duration_s << " s of " << s.path_length_m << " m path), " << s.structure_scans
            << " structure scans, " << s.images << " images, ";
  if (const VoxelWorld* voxels = simulator.voxels()) {
    std::cerr << s.occupied_voxels << " occupied voxels of " << voxels->info().file;
  } else {
    std::cerr << s.surfaces << " surfaces";
  }
  std::cerr << " -> " << s.paths.rawlog.string() << "\n";
  return s;
}

}  // namespace pmap::sim
