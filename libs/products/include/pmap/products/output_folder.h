// A planar-mapper output folder as its readers (map-eval, the report) see
// it: only the files the run's manifest.json lists, and only when their size
// and SHA-256 match it (doc/outputs.md, "Reading an output folder"). A file
// left by an earlier run, or changed after the run, is refused by name. A
// folder written before manifests existed is read as before (its files
// unchecked), with one warning. map-eval's own outputs (eval.json,
// octomap_*.bt) are exempt: they are no part of the run.
#pragma once

#include <filesystem>
#include <optional>
#include <set>
#include <string>

#include "pmap/products/output_manifest.h"

namespace pmap::products {

class OutputFolder {
 public:
  /// Opens `dir` and reads DIR/manifest.json when there is one. Throws
  /// InputError when the manifest is malformed (readManifest).
  explicit OutputFolder(std::filesystem::path dir);

  const std::filesystem::path& dir() const { return dir_; }
  bool hasManifest() const { return manifest_.has_value(); }
  const OutputManifest* manifest() const { return manifest_ ? &*manifest_ : nullptr; }

  /// Without a manifest, the one warning a reader prints; empty otherwise.
  std::string warning() const;

  /// Whether the run wrote `name` (relative path): the manifest lists it;
  /// without a manifest, and for exempt names, whether the file exists.
  bool has(const std::string& name) const;

  /// DIR/name, checked: the manifest lists it and the file's size and
  /// SHA-256 equal the manifest's (each file is hashed once). Without a
  /// manifest, and for exempt names: DIR/name unchecked. Throws InputError
  /// naming the file: "DIR/NAME: not in DIR/manifest.json (...)", "...:
  /// listed in DIR/manifest.json but missing", "...: does not match
  /// DIR/manifest.json (...)".
  std::filesystem::path file(const std::string& name) const;

  /// Checks every file the manifest lists (file()); throws InputError
  /// naming the first that does not match. Nothing to check without one.
  void verify() const;

 private:
  std::filesystem::path dir_;
  std::optional<OutputManifest> manifest_;
  mutable std::set<std::string> verified_;
};

}  // namespace pmap::products
