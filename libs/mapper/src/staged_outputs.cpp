#include "pmap/mapper/staged_outputs.h"

#include <unistd.h>

#include <system_error>

#include "pmap/common/error.h"
#include "pmap/mapper/output_guard.h"
#include "pmap/products/output_layout.h"

namespace pmap::mapper {
namespace fs = std::filesystem;

namespace {

fs::path resolvedTarget(const fs::path& out) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(out, ec).lexically_normal();
  fs::path r = fs::weakly_canonical(absolute, ec);
  r = ec ? absolute : r;
  return r.has_filename() ? r : r.parent_path();  // "dir/" -> "dir"
}

/// The parent must exist and be writable: the staging folder goes there.
void createParent(const fs::path& target, const std::string& shown) {
  const fs::path parent = target.parent_path();
  std::error_code ec;
  if (target.filename().empty() || parent == target) {
    throw OutputError(shown + ": cannot be an output folder (the root)");
  }
  fs::create_directories(parent, ec);
  if (ec) {
    throw OutputError(shown + ": cannot create output directory: " + ec.message());
  }
  if (::access(parent.c_str(), W_OK | X_OK) != 0) {
    throw OutputError(shown + ": cannot create output directory: " + parent.string() +
                      " is not writable (a run writes beside its output folder, then swaps it in)");
  }
}

/// True when the current directory is `dir` or inside it.
bool holdsCurrentDirectory(const fs::path& dir) {
  std::error_code ec;
  const fs::path cwd = fs::current_path(ec);
  const fs::path rel = cwd.lexically_relative(dir);
  return !ec && !rel.empty() && *rel.begin() != "..";
}

}  // namespace

StagedOutputs::StagedOutputs(const fs::path& out, StagedDirectory::Hooks hooks)
    : shown_(out.string()), target_(resolvedTarget(out)) {
  createParent(target_, shown_);
  const fs::path lock_file = StagedDirectory::siblingPath(target_, "lock", 0);
  try {
    lock_.emplace(lock_file);
  } catch (const LockHeld& e) {
    const std::string pid = e.holderPid() > 0 ? std::to_string(e.holderPid()) : "unknown";
    throw OutputError(shown_ + ": another run (pid " + pid +
                      ") is writing into this folder (lock " + lock_file.string() +
                      "); wait for it to end or choose another --out");
  } catch (const OutputError& e) {
    throw OutputError(shown_ + ": " + e.what());
  }
  if (lock_->stalePid() > 0) {
    warnings_.push_back(shown_ + ": took over the lock of pid " +
                        std::to_string(lock_->stalePid()) +
                        ", which ended without releasing it (killed?)");
  }
  for (std::string& note : StagedDirectory::recover(target_)) {
    warnings_.push_back(std::move(note));
  }
  checkOutputFolder(target_, shown_);
  if (holdsCurrentDirectory(target_)) {
    warnings_.push_back(shown_ +
                        " holds the current directory; the run replaces that folder as a "
                        "whole: cd into it again to see the new files");
  }
  staged_.emplace(target_, std::move(hooks));
}

std::vector<std::string> StagedOutputs::commit(products::OutputManifest manifest) {
  products::writeManifest(staged_->path(), std::move(manifest));
  std::vector<std::string> notes = staged_->commit([](const fs::path& rel) {
    return !products::OutputLayout::names(rel.generic_string());  // not ours: stays in place
  });
  lock_->release();
  return notes;
}

}  // namespace pmap::mapper
