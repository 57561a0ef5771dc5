// Several outputs that are replaced together or not at all (a rawlog, its
// image directory and its ground truth; a map and its textures).
//
// Each output is written under a temporary name, "<target>.tmp-<pid>" (a file
// or a directory), that add() hands out. commit() then puts the whole set in
// place with renames in the same directory:
//   1. every existing target is renamed to "<target>.old-<pid>" (its backup);
//   2. every temporary is renamed to its target;
//   3. the backups are removed.
// If any rename of steps 1-2 fails, the renames already done are undone in
// reverse order and the temporaries are removed: every target is then as it
// was before (absent if it was absent), and commit() throws OutputError
// naming the target. A destroyed set that was not committed removes its
// temporaries.
//
// What is not atomic (POSIX has no multi-file rename): between the first
// backup and the last install (2 renames per output, microseconds) a reader
// may find some targets missing or already new; a process killed in that
// window (SIGKILL, power loss) leaves the old outputs under their ".old-<pid>"
// names beside some new ones. If an undo rename fails too (the filesystem
// broke down mid-commit), the message says where each old output is. Step 3
// is best effort: a backup that cannot be removed stays beside the new set.
#pragma once

#include <filesystem>
#include <functional>
#include <system_error>
#include <vector>

namespace pmap {

class OutputSet {
 public:
  enum class Kind { kFile, kDirectory };
  /// The rename used by commit(); std::filesystem::rename by default.
  using RenameFunction = std::function<void(const std::filesystem::path& from,
                                            const std::filesystem::path& to, std::error_code&)>;

  explicit OutputSet(RenameFunction rename = {});
  ~OutputSet();  ///< removes the temporaries unless committed
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  /// Registers `target` and returns its temporary path. Creates the target's
  /// directory; for kDirectory also the (empty) temporary directory. Throws
  /// OutputError if the directory is not writable or `target` exists and is
  /// not of `kind` (a directory where a file goes is never replaced).
  std::filesystem::path add(const std::filesystem::path& target, Kind kind);

  /// Puts every temporary in place, all or nothing (see above). Every
  /// temporary must exist. Throws OutputError.
  void commit();

 private:
  struct Entry {
    std::filesystem::path target;
    std::filesystem::path temporary;
    std::filesystem::path backup;
    Kind kind;
    bool had_target = false;
  };
  struct Move {
    std::filesystem::path from;
    std::filesystem::path to;
  };
  void moveOrRollBack(const std::filesystem::path& from, const std::filesystem::path& to,
                      const Entry& entry, std::vector<Move>& done);
  [[noreturn]] void rollBack(const std::vector<Move>& done, const std::string& what);
  void removeTemporaries();

  RenameFunction rename_;
  std::vector<Entry> entries_;
  bool committed_ = false;
};

}  // namespace pmap
