// Locating config/worlds/default.json (see defaultWorldCandidates()).
#include <unistd.h>

#include <filesystem>

#include "pmap/common/error.h"
#include "pmap/sim/indoor_sim_app.h"

#ifndef PMAP_SIM_SOURCE_WORLDS_DIR
#define PMAP_SIM_SOURCE_WORLDS_DIR ""
#endif
#ifndef PMAP_SIM_INSTALLED_WORLDS_DIR
#define PMAP_SIM_INSTALLED_WORLDS_DIR ""
#endif

namespace pmap::sim {
namespace fs = std::filesystem;

std::vector<std::string> defaultWorldCandidates() {
  std::vector<std::string> out;
  for (const std::string dir : {PMAP_SIM_SOURCE_WORLDS_DIR, PMAP_SIM_INSTALLED_WORLDS_DIR}) {
    if (!dir.empty()) {
      out.push_back((fs::path(dir) / "default.json").string());
    }
  }
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    out.push_back(
        (exe.parent_path().parent_path() / "share/planar_mapper/worlds/default.json").string());
  }
  return out;
}

std::string findDefaultWorld() {
  const std::vector<std::string> candidates = defaultWorldCandidates();
  std::string tried;
  for (const std::string& c : candidates) {
    std::error_code ec;
    if (fs::is_regular_file(c, ec)) {
      return c;
    }
    tried += (tried.empty() ? "" : ", ") + c;
  }
  throw ConfigError("no default world found (tried " + tried + "); pass --world FILE");
}

}  // namespace pmap::sim
