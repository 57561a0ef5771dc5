#include "pmap/products/output_folder.h"

#include <system_error>

#include "pmap/common/error.h"
#include "pmap/common/sha256.h"
#include "pmap/products/output_layout.h"

namespace pmap::products {
namespace fs = std::filesystem;

OutputFolder::OutputFolder(fs::path dir) : dir_(std::move(dir)) {
  const fs::path file = dir_ / OutputLayout::kManifest;
  std::error_code ec;
  if (fs::exists(fs::symlink_status(file, ec))) {
    manifest_ = readManifest(file);
  }
}

std::string OutputFolder::warning() const {
  if (manifest_) {
    return {};
  }
  return dir_.string() + ": no " + OutputLayout::kManifest +
         " (written before planar-mapper wrote manifests): its files are read unchecked and "
         "may come from different runs";
}

bool OutputFolder::has(const std::string& name) const {
  if (!manifest_ || OutputLayout::manifestExempt(name)) {
    std::error_code ec;
    return fs::exists(dir_ / name, ec);
  }
  return manifest_->find(name) != nullptr;
}

fs::path OutputFolder::file(const std::string& name) const {
  const fs::path path = dir_ / name;
  if (!manifest_ || OutputLayout::manifestExempt(name) || verified_.count(name) != 0) {
    return path;
  }
  const std::string manifest_path = (dir_ / OutputLayout::kManifest).string();
  const ManifestFile* entry = manifest_->find(name);
  if (entry == nullptr) {
    throw InputError(path.string() + ": not in " + manifest_path +
                     " (not written by that run; left by another?)");
  }
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(path, ec);
  if (!fs::exists(status)) {
    throw InputError(path.string() + ": listed in " + manifest_path + " but missing");
  }
  if (!fs::is_regular_file(status)) {
    throw InputError(path.string() + ": listed in " + manifest_path + " but not a regular file");
  }
  const std::uint64_t bytes = fs::file_size(path, ec);
  if (bytes != entry->bytes) {
    throw InputError(path.string() + ": does not match " + manifest_path + " (" +
                     std::to_string(bytes) + " bytes, the manifest says " +
                     std::to_string(entry->bytes) + "; changed or left by another run)");
  }
  if (fileSha256(path) != entry->sha256) {
    throw InputError(path.string() + ": does not match " + manifest_path +
                     " (SHA-256 differs; changed or left by another run)");
  }
  verified_.insert(name);
  return path;
}

void OutputFolder::verify() const {
  if (!manifest_) {
    return;
  }
  for (const ManifestFile& f : manifest_->files) {
    file(f.path);
  }
}

}  // namespace pmap::products
