#include "pmap/common/output_set.h"

#include <unistd.h>

#include <cassert>
#include <string>

#include "pmap/common/atomic_file.h"
#include "pmap/common/error.h"

namespace pmap {
namespace fs = std::filesystem;
namespace {

/// Why `target` cannot be replaced by an output of `kind`; empty if it can.
std::string kindProblem(const fs::path& target, OutputSet::Kind kind) {
  std::error_code ec;
  const fs::file_status status = fs::status(target, ec);
  if (!fs::exists(status)) {
    return {};
  }
  if (kind == OutputSet::Kind::kDirectory && !fs::is_directory(status)) {
    return target.string() + ": exists and is not a directory";
  }
  if (kind == OutputSet::Kind::kFile && fs::is_directory(status)) {
    return target.string() + ": exists and is a directory";
  }
  return {};
}

void defaultRename(const fs::path& from, const fs::path& to, std::error_code& ec) {
  fs::rename(from, to, ec);
}

}  // namespace

OutputSet::OutputSet(RenameFunction rename)
    : rename_(rename ? std::move(rename) : RenameFunction(defaultRename)) {}

OutputSet::~OutputSet() {
  if (!committed_) {
    removeTemporaries();
  }
}

fs::path OutputSet::add(const fs::path& target, Kind kind) {
  assert(!committed_);
  const fs::path parent = target.parent_path();
  ensureWritableDirectory(parent.empty() ? fs::path(".") : parent);
  if (const std::string problem = kindProblem(target, kind); !problem.empty()) {
    throw OutputError(problem);
  }
  const std::string pid = std::to_string(::getpid());
  Entry entry{target, target.string() + ".tmp-" + pid, target.string() + ".old-" + pid, kind};
  std::error_code ec;
  fs::remove_all(entry.temporary, ec);  // left by an earlier process with this pid
  if (kind == Kind::kDirectory && !fs::create_directory(entry.temporary, ec)) {
    throw OutputError(target.string() + ": cannot create the temporary directory " +
                      entry.temporary.string() + ": " + ec.message());
  }
  entries_.push_back(entry);
  return entries_.back().temporary;
}

void OutputSet::commit() {
  assert(!committed_);
  std::vector<Move> done;
  for (Entry& entry : entries_) {
    std::error_code ec;
    entry.had_target = fs::exists(fs::symlink_status(entry.target, ec));
    if (!entry.had_target) {
      continue;
    }
    if (const std::string problem = kindProblem(entry.target, entry.kind); !problem.empty()) {
      rollBack(done, problem);
    }
    moveOrRollBack(entry.target, entry.backup, entry, done);
  }
  for (const Entry& entry : entries_) {
    moveOrRollBack(entry.temporary, entry.target, entry, done);
  }
  committed_ = true;
  for (const Entry& entry : entries_) {
    if (entry.had_target) {
      std::error_code ec;
      fs::remove_all(entry.backup, ec);
    }
  }
}

void OutputSet::moveOrRollBack(const fs::path& from, const fs::path& to, const Entry& entry,
                               std::vector<Move>& done) {
  std::error_code ec;
  rename_(from, to, ec);
  if (ec) {
    const std::string step = to == entry.backup
                                 ? "cannot move the previous output aside to " + to.string()
                                 : "cannot move the new output into place from " + from.string();
    rollBack(done, entry.target.string() + ": " + step + ": " + ec.message());
  }
  done.push_back({from, to});
}

void OutputSet::rollBack(const std::vector<Move>& done, const std::string& what) {
  std::string failures;
  for (auto it = done.rbegin(); it != done.rend(); ++it) {
    std::error_code ec;
    rename_(it->to, it->from, ec);
    if (ec) {
      failures += "; could not move " + it->to.string() + " back to " + it->from.string() + ": " +
                  ec.message();
    }
  }
  removeTemporaries();
  throw OutputError(what + (failures.empty() ? " (nothing was replaced)" : failures));
}

void OutputSet::removeTemporaries() {
  for (const Entry& entry : entries_) {
    std::error_code ec;
    fs::remove_all(entry.temporary, ec);
  }
}

}  // namespace pmap
