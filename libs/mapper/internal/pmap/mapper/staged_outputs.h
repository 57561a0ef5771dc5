// The output folder of one run, replaced as a whole (doc/outputs.md, "How a
// run replaces its folder"):
//  1. takes the folder's lock, .NAME.lock beside it: a second run on the same
//     --out is refused (exit 4) naming the holder's pid; a lock its holder
//     could not release (SIGKILL) is taken over with a warning;
//  2. finishes or undoes a swap a crash interrupted and removes the staging
//     folders of earlier runs that did not end cleanly (StagedDirectory);
//  3. checks the folder (checkOutputFolder: no foreign files without a
//     manifest, no mount point, writable);
//  4. creates the staging folder .NAME.staging-PID beside it: the run writes
//     every output there (dir());
//  5. commit(): writes manifest.json, keeps the entries the layout does not
//     name in place, swaps the staging folder in (the previous run's files
//     go with the previous folder), releases the lock.
// Destroyed without commit (an error, an interrupt): the staging folder is
// removed and the lock released; the previous folder is untouched.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "pmap/common/pid_lock.h"
#include "pmap/common/staged_directory.h"
#include "pmap/products/output_manifest.h"

namespace pmap::mapper {

class StagedOutputs {
 public:
  /// Steps 1-4 for --out `out`. Throws OutputError (exit 4).
  explicit StagedOutputs(const std::filesystem::path& out,
                         StagedDirectory::Hooks hooks = StagedDirectory::Hooks{});

  /// The staging folder, where the run writes.
  const std::filesystem::path& dir() const { return staged_->path(); }
  /// --out, absolute, links resolved.
  const std::filesystem::path& target() const { return target_; }
  /// Lines for the run's warnings: a lock taken over, a swap finished,
  /// leftovers removed, --out holding the current directory.
  const std::vector<std::string>& warnings() const { return warnings_; }

  /// Step 5: `manifest` (program, command, config hash) gets the files
  /// listed. Returns notes about kept entries, normally none. Throws
  /// OutputError; the previous folder is then in place.
  std::vector<std::string> commit(products::OutputManifest manifest);

 private:
  std::string shown_;  ///< --out as given
  std::filesystem::path target_;
  std::optional<PidLock> lock_;  // declared before staged_: released after it is removed
  std::optional<StagedDirectory> staged_;
  std::vector<std::string> warnings_;
};

}  // namespace pmap::mapper
