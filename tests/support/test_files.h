// Files and folders for tests: fresh per-process folders, whole-file text
// read and write, and a snapshot of a folder's contents to compare.
#pragma once

#include <filesystem>
#include <map>
#include <string>

namespace pmap::testing {

/// A fresh, empty folder `<test tmp>/<group>/<name>/<pid>`, canonical: CTest
/// runs the test cases of one binary in parallel processes.
std::filesystem::path processTestDir(const std::string& group, const std::string& name);

/// Writes `text` to `path`, creating its folders.
void writeText(const std::filesystem::path& path, const std::string& text);

/// The whole file's bytes ("" when it cannot be read).
std::string readText(const std::filesystem::path& path);

/// config/default.ini with the first `from` replaced by `to` (throws when
/// there is none), written as `dir/my.ini` with config/icp.ini beside it for
/// its @include.
std::filesystem::path editedDefaultIni(const std::filesystem::path& dir, const std::string& from,
                                       const std::string& to);

/// Every entry under `dir`: relative path ('/'-separated) -> content, "<dir>"
/// for folders.
std::map<std::string, std::string> snapshot(const std::filesystem::path& dir);

}  // namespace pmap::testing
