// Shared helpers of the bad-input tables.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "rawlog_fixtures.h"

namespace pmap::testing {

/// Writes a fixture rawlog dir/name and returns its path.
std::filesystem::path writeFixture(const std::filesystem::path& dir, FixtureOptions o = {},
                                   const std::string& name = "log.rawlog");

/// planar-mapper --rawlog RAWLOG --out DIR/out -q EXTRA...
std::vector<std::string> mapArgs(const std::filesystem::path& rawlog,
                                 const std::filesystem::path& dir,
                                 const std::vector<std::string>& extra = {});

/// dir/out/summary.json.
nlohmann::json readSummary(const std::filesystem::path& dir);

/// Copies config/default.ini (as my.ini) and config/icp.ini into dir, with the
/// first `from` in them replaced by `to` (both may be empty); returns my.ini.
std::filesystem::path editedConfig(const std::filesystem::path& dir, const std::string& from,
                                   const std::string& to);

/// Checks that dir/out holds a complete, readable map (points.ply reads back
/// with finite coordinates, summary.json parses) and returns the summary.
nlohmann::json expectValidMap(const std::filesystem::path& dir);

}  // namespace pmap::testing
