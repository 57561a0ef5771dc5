// manifest.json: what one planar-mapper run wrote into its output folder
// (doc/outputs.md, "The manifest"): every file with its size and SHA-256,
// the command and the hash of the configuration. Written last, into the
// staging folder, just before the folder is swapped in; readers (map-eval,
// the report) read only the files it lists, and only when they match it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace pmap::products {

struct ManifestFile {
  std::string path;  ///< relative to the folder, '/'-separated
  std::uint64_t bytes = 0;
  std::string sha256;  ///< 64 lowercase hex digits
};

struct OutputManifest {
  static constexpr const char* kFormat = "planar-mapper-manifest";
  static constexpr int kVersion = 1;

  std::string program;               ///< "planar-mapper 0.1.0"
  std::vector<std::string> command;  ///< argv as given
  std::string config_sha256;         ///< SHA-256 of the effective configuration
  std::string written_utc;           ///< ISO 8601, e.g. 2025-12-02T04:36:00Z
  std::vector<ManifestFile> files;   ///< sorted by path; manifest.json not included

  /// The entry of `path`, or nullptr.
  const ManifestFile* find(const std::string& path) const;

  /// The document, keys in the order of doc/outputs.md.
  nlohmann::ordered_json toJson() const;
};

/// Every regular file under `dir` (recursively; links and other types are
/// not followed), except DIR/manifest.json: path, size and SHA-256, sorted by
/// path. Throws OutputError naming a file that cannot be read.
std::vector<ManifestFile> listFiles(const std::filesystem::path& dir);

/// Lists `dir` into manifest.files and writes DIR/manifest.json atomically.
/// Throws OutputError.
void writeManifest(const std::filesystem::path& dir, OutputManifest manifest);

/// Reads a manifest.json. Throws InputError naming the file (and the entry)
/// when it is not valid JSON, not a manifest of this format and version, or
/// lists a path that leaves the folder, a duplicate, a bad size or digest.
OutputManifest readManifest(const std::filesystem::path& file);

/// The current UTC time as ISO 8601 ("2025-12-02T04:36:00Z").
std::string utcNow();

}  // namespace pmap::products
