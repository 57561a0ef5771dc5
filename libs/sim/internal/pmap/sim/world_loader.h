// Strict loading of world files (config/worlds/*.json, format in
// doc/simulator.md). Unknown keys (with the nearest known key suggested), wrong
// types, out-of-range values, missing required keys and duplicate keys are
// ConfigErrors naming the file and the JSON path.
#pragma once

#include <filesystem>
#include <string>

#include "pmap/sim/world_spec.h"

namespace pmap::sim {

/// Reads and parses a world file; a missing or unreadable file is a ConfigError.
WorldSpec loadWorldFile(const std::filesystem::path& path);

/// Parses world JSON text; `file_name` is used in error messages.
WorldSpec parseWorldText(const std::string& text, const std::string& file_name);

}  // namespace pmap::sim
