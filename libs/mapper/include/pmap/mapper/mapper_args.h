// Command line of planar-mapper (parsed with TCLAP, as MRPT's own apps).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "pmap/input/observation_source.h"
#include "pmap/mapper/mapping_result.h"

namespace pmap::mapper {

struct MapperArgs {
  std::filesystem::path config;   ///< ini (default: config/default.ini)
  std::filesystem::path rawlog;   ///< input rawlog (default: the bundled sample)
  bool rawlog_is_sample = false;  ///< no --rawlog / --cloud: the bundled sample
  std::filesystem::path cloud;    ///< --cloud FILE.ply instead of a rawlog
  std::filesystem::path poses;    ///< --poses FILE: given poses instead of ICP
  std::filesystem::path out = "planar-mapper-out";
  MapMode mode = MapMode::kOnline;  ///< --mode
  int snapshot_every = 0;           ///< online: write the map every N structure scans
  double playback_rate = 0.0;       ///< feed scans at R x their recorded pace (0: at once)
  bool poses_only = false;
  bool list_labels = false;  ///< --list-labels: print the rawlog's labels and exit
  bool accept_truncated = false;
  bool quiet = false;        ///< no progress line
  bool no_textures = false;  ///< geometry only
  bool no_refine = false;    ///< the EM's map as it is (as [Refinement] enabled = false)
  bool gui = false;          ///< live 3D window
  double gui_hold_s = -1.0;  ///< --gui: final map shown this long (< 0: until closed)

  input::SelectionOptions selection;
};

/// Parses argv. Returns nullopt after printing --help / --version (exit 0).
/// Throws ConfigError for bad usage.
std::optional<MapperArgs> parseMapperArgs(int argc, const char* const* argv);

/// Where the bundled files live: the source tree this binary was built from,
/// else the installed share directory.
std::filesystem::path defaultConfigPath();
std::filesystem::path defaultSamplePath();

}  // namespace pmap::mapper
