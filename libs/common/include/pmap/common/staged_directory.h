// A directory replaced as a whole (a run's output folder): the new content is
// written into a staging directory beside the target and swapped in at the
// end, so that a reader, a full disk, a signal or a crash finds either the
// whole previous directory or the whole new one, never a mix.
//
// Names in the target's parent (NAME: the target's file name, PID: the
// writing process):
//   .NAME.staging-PID  the new content while it is written
//   .NAME.ready-PID    two-rename swap: the complete new content
//   .NAME.old-PID      two-rename swap: the previous content until removed
//   .NAME.kept-PID     the previous content, kept because an entry `keep`
//                      selects could not be linked into the new one (never
//                      removed automatically)
//
// commit(keep):
//  1. every entry of the target that `keep` selects (what the writer does not
//     own, e.g. a user's notes) is hard-linked into the staging directory
//     (directories are recreated): the same files, never copied, moved or
//     deleted, present under their path before, during and after the swap;
//  2. the swap: renameat2(RENAME_EXCHANGE) of the staging directory and the
//     target, atomic, where the file system has it; else three renames:
//     staging -> ready, target -> old, ready -> target (a crash between the
//     last two leaves no NAME: recover() finishes the swap). Without a target:
//     staging -> target;
//  3. entries `keep` selects that appeared in the previous content during
//     steps 1-2 are linked into the new one; the previous content is removed.
// A StagedDirectory destroyed without commit (an error, an interrupt) removes
// its staging directory: the target is untouched.
//
// recover(target), at the start of the next writer and under its lock
// (pid_lock.h): finishes a two-rename swap that a crash interrupted (no NAME
// but a ready directory: ready -> NAME; only an old one: old -> NAME) and
// removes the staging, ready and old directories earlier processes left
// (SIGKILL and power loss cannot be cleaned up after sooner).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <system_error>
#include <vector>

namespace pmap {

class StagedDirectory {
 public:
  /// Selects, by path relative to the target, the entries commit() keeps.
  using KeepFunction = std::function<bool(const std::filesystem::path& relative)>;
  using RenameFunction = std::function<void(const std::filesystem::path& from,
                                            const std::filesystem::path& to, std::error_code&)>;
  /// Fault injection for tests; the defaults are the real system calls.
  struct Hooks {
    RenameFunction rename;    ///< plain renames (std::filesystem::rename)
    RenameFunction exchange;  ///< renameat2(RENAME_EXCHANGE); an error of
                              ///< "not supported" falls back to three renames
  };

  /// Creates the staging directory .NAME.staging-PID beside `target` (an
  /// absolute path without symbolic links; its parent is created if needed)
  /// with the target's permissions. Throws OutputError naming the target.
  explicit StagedDirectory(std::filesystem::path target, Hooks hooks = {});
  ~StagedDirectory();  ///< removes the staging directory unless committed
  StagedDirectory(const StagedDirectory&) = delete;
  StagedDirectory& operator=(const StagedDirectory&) = delete;

  /// Where the new content is written.
  const std::filesystem::path& path() const { return staging_; }
  const std::filesystem::path& target() const { return target_; }

  /// Swaps the staging directory in (see above). Throws OutputError naming
  /// the target when the swap fails; the target is then as it was, or the
  /// message says where the previous content is. Returns notes (one line
  /// each) about what needed attention, normally none.
  std::vector<std::string> commit(const KeepFunction& keep = {});

  /// See above. Returns one note per directory renamed or removed.
  static std::vector<std::string> recover(const std::filesystem::path& target);

  /// "<parent>/.NAME.<kind>-<pid>" for kind staging, ready, old, kept; and
  /// "<parent>/.NAME.lock" for kind "lock" (pid ignored).
  static std::filesystem::path siblingPath(const std::filesystem::path& target,
                                           const std::string& kind, long pid);

 private:
  std::filesystem::path swapWithRenames();
  void keepLateArrivals(const std::filesystem::path& previous, const KeepFunction& keep,
                        std::vector<std::string>& notes);
  void rename(const std::filesystem::path& from, const std::filesystem::path& to,
              std::error_code& ec) const;

  std::filesystem::path target_;
  std::filesystem::path staging_;
  std::filesystem::path current_;  ///< where the new content is now (removed if not committed)
  Hooks hooks_;
  bool committed_ = false;
};

/// True when `dir` is a mount point (or the root): it cannot be renamed, so
/// it cannot be replaced as a whole.
bool isMountPoint(const std::filesystem::path& dir);

}  // namespace pmap
