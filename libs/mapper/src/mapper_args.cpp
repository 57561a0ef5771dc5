#include "pmap/mapper/mapper_args.h"

#include <cmath>
#include <sstream>

#include "pmap/common/error.h"
#include "pmap/common/text.h"
#include "pmap/config/command_line.h"

namespace pmap::mapper {
namespace fs = std::filesystem;

namespace {

fs::path firstExisting(const std::vector<fs::path>& candidates) {
  for (const auto& c : candidates) {
    std::error_code ec;
    if (fs::exists(c, ec)) {
      return c;
    }
  }
  return candidates.front();
}

const char* kDescription =
    "planar-mapper: builds a compact 3D map of rectangles (walls, doors, ceiling) plus fine "
    "triangles from an MRPT rawlog: MRPT's 2D ICP on odometry and the horizontal laser gives "
    "the poses; the structure sensors (a vertical 2D laser, 3D range frames) give the points. "
    "Without arguments it maps the bundled sample with config/default.ini. Exit codes: 0 ok, "
    "1 usage or configuration error, 2 input data error, 3 processing failure, 4 output "
    "write error.";

}  // namespace

fs::path defaultConfigPath() {
  return firstExisting({fs::path(PMAP_SOURCE_DIR) / "config/default.ini",
                        fs::path(PMAP_INSTALL_SHARE_DIR) / "config/default.ini"});
}

fs::path defaultSamplePath() {
  return firstExisting({fs::path(PMAP_SOURCE_DIR) / "share/sample/default-L.rawlog",
                        fs::path(PMAP_INSTALL_SHARE_DIR) / "sample/default-L.rawlog"});
}

std::optional<MapperArgs> parseMapperArgs(int argc, const char* const* argv) {
  TCLAP::CmdLine cmd(kDescription, ' ', "0.1.0");
  TCLAP::ValueArg<std::string> config("c", "config", "ini file (default: config/default.ini)",
                                      false, "", "FILE.ini", cmd);
  TCLAP::ValueArg<std::string> rawlog("r", "rawlog", "input rawlog (plain or gzip)", false, "",
                                      "FILE.rawlog", cmd);
  TCLAP::ValueArg<std::string> cloud("", "cloud", "map this point cloud instead of a rawlog", false,
                                     "", "FILE.ply", cmd);
  TCLAP::ValueArg<std::string> poses(
      "", "poses", "use these poses (poses.txt format) instead of ICP", false, "", "FILE", cmd);
  TCLAP::ValueArg<std::string> out("o", "out", "output directory", false, "planar-mapper-out",
                                   "DIR", cmd);
  std::vector<std::string> modes = {toString(MapMode::kOnline), toString(MapMode::kOffline),
                                    toString(MapMode::kRaw)};
  TCLAP::ValuesConstraint<std::string> mode_values(modes);
  TCLAP::ValueArg<std::string> mode(
      "", "mode",
      "online: the planar map is updated after every scan (default); offline: EM over all "
      "measurements at the end; raw: points and the raw polygon map only",
      false, "online", &mode_values, cmd);
  TCLAP::ValueArg<long long> snapshot("", "snapshot-every",
                                      "online: also write the map every N structure scans "
                                      "(OUT/snapshots/map_NNNNNN.wrl)",
                                      false, 0, "N", cmd);
  TCLAP::ValueArg<double> playback("", "playback-rate",
                                   "feed the log at R times its recorded pace (1 = real time; "
                                   "default 0 = as fast as possible)",
                                   false, 0.0, "R", cmd);
  TCLAP::SwitchArg poses_only("", "poses-only", "only run the pose stage and write poses.txt", cmd);
  TCLAP::ValueArg<long long> from("", "from-index", "first rawlog record to use (as rawlog-edit)",
                                  false, 0, "N", cmd);
  TCLAP::ValueArg<long long> to("", "to-index", "last rawlog record to use (inclusive)", false, -1,
                                "N", cmd);
  TCLAP::MultiArg<std::string> keep("", "keep-label",
                                    "keep only observations with this sensor label (repeatable, "
                                    "or comma-separated)",
                                    false, "LABEL", cmd);
  TCLAP::ValueArg<long long> decimate("", "decimate", "use every N-th structure scan", false, 1,
                                      "N", cmd);
  TCLAP::SwitchArg skip_leading("", "skip-leading-frame",
                                "drop a sensory frame with no action before it, as MRPT's pair "
                                "reader and icp-slam do",
                                cmd);
  TCLAP::SwitchArg accept_truncated("", "accept-truncated",
                                    "map the complete records of a truncated rawlog", cmd);
  TCLAP::SwitchArg no_textures(
      "", "no-textures", "geometry only: no camera textures (as [Texture] enabled = false)", cmd);
  TCLAP::SwitchArg no_refine(
      "", "no-refine",
      "write the EM's map without fusion and boundary refinement (as [Refinement] enabled = "
      "false)",
      cmd);
  TCLAP::SwitchArg gui("", "gui",
                       "show the growing map, the current scans and the robot in a 3D window "
                       "while mapping (MRPT display window, as icp-slam)",
                       cmd);
  TCLAP::ValueArg<double> gui_hold("", "gui-hold",
                                   "with --gui: keep the final map shown S seconds, then exit "
                                   "(default: until the window is closed or a key pressed)",
                                   false, -1.0, "S", cmd);
  TCLAP::SwitchArg list_labels("", "list-labels",
                               "print the sensor labels of the rawlog (class, label, count, first "
                               "record) and exit",
                               cmd);
  TCLAP::SwitchArg quiet("q", "quiet", "no progress line", cmd);

  if (!config::parseCommandLine(cmd, argc, argv)) {
    return std::nullopt;
  }

  MapperArgs a;
  a.config = config.getValue().empty() ? defaultConfigPath() : fs::path(config.getValue());
  a.cloud = cloud.getValue();
  a.poses = poses.getValue();
  a.out = out.getValue();
  if (!a.cloud.empty() && !rawlog.getValue().empty()) {
    throw ConfigError("usage: --cloud and --rawlog are exclusive");
  }
  if (!rawlog.getValue().empty()) {
    a.rawlog = rawlog.getValue();
  } else if (a.cloud.empty() && config.isSet()) {
    // The bundled sample goes with the default configuration only: another
    // ini is for another log, which the user forgot to name.
    throw ConfigError("usage: --config " + config.getValue() +
                      " needs an input: give --rawlog FILE or --cloud FILE.ply (without "
                      "--config, planar-mapper maps its bundled sample)");
  } else if (a.cloud.empty()) {
    a.rawlog = defaultSamplePath();
    a.rawlog_is_sample = true;
  }
  a.list_labels = list_labels.getValue();
  if (a.list_labels && !a.cloud.empty()) {
    throw ConfigError("usage: --list-labels reads a rawlog, not a --cloud");
  }
  a.mode = *parseMapMode(mode.getValue());  // TCLAP checked the values
  if (snapshot.getValue() < 0 || snapshot.getValue() > 1000000000 ||
      !(playback.getValue() >= 0.0) || !std::isfinite(playback.getValue())) {
    throw ConfigError("usage: --snapshot-every must be >= 0 and --playback-rate a number >= 0");
  }
  if (snapshot.getValue() > 0 && (a.mode != MapMode::kOnline || poses_only.getValue())) {
    throw ConfigError(
        "usage: --snapshot-every writes the online map while it grows: it needs "
        "--mode online (the default), not --mode " +
        (poses_only.getValue() ? std::string("with --poses-only") : toString(a.mode)));
  }
  a.snapshot_every = static_cast<int>(snapshot.getValue());
  a.playback_rate = playback.getValue();
  a.poses_only = poses_only.getValue();
  a.accept_truncated = accept_truncated.getValue();
  a.quiet = quiet.getValue();
  a.no_textures = no_textures.getValue();
  a.no_refine = no_refine.getValue();
  a.gui = gui.getValue();
  a.gui_hold_s = gui_hold.getValue();
  if (gui_hold.isSet() && (!a.gui || !(a.gui_hold_s >= 0.0 && a.gui_hold_s <= 86400.0))) {
    throw ConfigError("usage: --gui-hold needs --gui and a number of seconds in [0, 86400]");
  }

  if (from.getValue() < 0 || decimate.getValue() < 1) {
    throw ConfigError("usage: --from-index must be >= 0 and --decimate >= 1");
  }
  a.selection.from_index = static_cast<std::size_t>(from.getValue());
  if (to.getValue() >= 0) {
    a.selection.to_index = static_cast<std::size_t>(to.getValue());
  }
  for (const auto& k : keep.getValue()) {
    for (const auto& label : splitFields(k, ",")) {
      a.selection.keep_labels.push_back(trim(label));
    }
  }
  a.selection.decimate = static_cast<std::size_t>(decimate.getValue());
  a.selection.skip_leading_frame = skip_leading.getValue();
  std::string why;
  if (!a.selection.validate(&why)) {
    throw ConfigError("usage: " + why);
  }
  return a;
}

}  // namespace pmap::mapper
