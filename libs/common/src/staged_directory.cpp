#include "pmap/common/staged_directory.h"

#include <fcntl.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cassert>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "pmap/common/error.h"

namespace pmap {
namespace fs = std::filesystem;
namespace {

void defaultRename(const fs::path& from, const fs::path& to, std::error_code& ec) {
  fs::rename(from, to, ec);
}

void defaultExchange(const fs::path& from, const fs::path& to, std::error_code& ec) {
  ec.clear();
  if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_EXCHANGE) != 0) {
    ec = std::error_code(errno, std::generic_category());
  }
}

/// staging -> target when there is no target; never over one that appeared.
void moveNoReplace(const fs::path& from, const fs::path& to, std::error_code& ec) {
  ec.clear();
  if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0) {
    return;
  }
  if (errno == EINVAL || errno == ENOSYS || errno == ENOTSUP) {
    if (::rename(from.c_str(), to.c_str()) == 0) {  // the file system has no RENAME_NOREPLACE
      return;
    }
  }
  ec = std::error_code(errno, std::generic_category());
}

bool notSupported(const std::error_code& ec) {
  return ec == std::errc::invalid_argument || ec == std::errc::function_not_supported ||
         ec == std::errc::not_supported || ec == std::errc::operation_not_supported;
}

bool isRealDirectory(const fs::path& p) {
  std::error_code ec;
  return fs::is_directory(fs::symlink_status(p, ec));
}

/// Hard-links `from` (a file, a link or a whole directory) to `to`.
void linkTree(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  if (isRealDirectory(from)) {
    fs::create_directories(to, ec);
    fs::permissions(to, fs::status(from, ec).permissions(), ec);
    for (const fs::directory_entry& e : fs::directory_iterator(from)) {
      linkTree(e.path(), to / e.path().filename());
    }
    return;
  }
  if (fs::exists(fs::symlink_status(to, ec))) {
    throw OutputError(from.string() + ": cannot keep it in place: the new outputs hold " +
                      to.filename().string() + " too");
  }
  fs::create_directories(to.parent_path(), ec);
  if (::link(from.c_str(), to.c_str()) != 0) {
    throw OutputError(from.string() + ": cannot keep it in place (hard link into " +
                      to.parent_path().string() + " failed: " + std::strerror(errno) + ")");
  }
}

/// Calls `found` for every entry under `root` that `keep` selects (not
/// descending into it); relative paths.
void forKept(const fs::path& root, const fs::path& relative,
             const StagedDirectory::KeepFunction& keep,
             const std::function<void(const fs::path&)>& found) {
  for (const fs::directory_entry& e : fs::directory_iterator(root / relative)) {
    const fs::path rel = relative / e.path().filename();
    if (keep(rel)) {
      found(rel);
    } else if (isRealDirectory(e.path())) {
      forKept(root, rel, keep, found);
    }
  }
}

struct Leftover {
  fs::path path;
  std::string kind;
  fs::file_time_type time;
};

/// The staging / ready / old directories of `target` in its parent.
std::vector<Leftover> leftovers(const fs::path& target) {
  std::vector<Leftover> found;
  const std::string prefix = "." + target.filename().string() + ".";
  static const std::regex kSuffix("(staging|ready|old)-[0-9]+");
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(target.parent_path(), ec)) {
    const std::string name = e.path().filename().string();
    std::smatch m;
    const std::string suffix = name.rfind(prefix, 0) == 0 ? name.substr(prefix.size()) : "";
    if (!suffix.empty() && std::regex_match(suffix, m, kSuffix) && isRealDirectory(e.path())) {
      found.push_back({e.path(), m[1].str(), fs::last_write_time(e.path(), ec)});
    }
  }
  return found;
}

}  // namespace

fs::path StagedDirectory::siblingPath(const fs::path& target, const std::string& kind, long pid) {
  const std::string name = "." + target.filename().string() + "." + kind;
  return target.parent_path() / (kind == "lock" ? name : name + "-" + std::to_string(pid));
}

StagedDirectory::StagedDirectory(fs::path target, Hooks hooks)
    : target_(std::move(target)), hooks_(std::move(hooks)) {
  assert(target_.is_absolute() && !target_.filename().empty());
  if (!hooks_.rename) {
    hooks_.rename = defaultRename;
  }
  if (!hooks_.exchange) {
    hooks_.exchange = defaultExchange;
  }
  staging_ = siblingPath(target_, "staging", ::getpid());
  std::error_code ec;
  fs::remove_all(staging_, ec);  // left by an earlier process with this pid
  fs::create_directories(target_.parent_path(), ec);
  if (ec || !fs::create_directory(staging_, ec)) {
    throw OutputError(target_.string() + ": cannot create the staging folder " + staging_.string() +
                      (ec ? ": " + ec.message() : ""));
  }
  if (isRealDirectory(target_)) {
    fs::permissions(staging_, fs::status(target_, ec).permissions(), ec);
  }
  current_ = staging_;
}

StagedDirectory::~StagedDirectory() {
  if (!committed_) {
    std::error_code ec;
    fs::remove_all(current_, ec);
  }
}

void StagedDirectory::rename(const fs::path& from, const fs::path& to, std::error_code& ec) const {
  hooks_.rename(from, to, ec);
}

std::vector<std::string> StagedDirectory::commit(const KeepFunction& keep) {
  assert(!committed_);
  std::vector<std::string> notes;
  std::error_code ec;
  const bool had_target = fs::exists(fs::symlink_status(target_, ec));
  if (had_target && !isRealDirectory(target_)) {
    throw OutputError(target_.string() + ": exists and is not a directory (nothing was replaced)");
  }
  if (had_target && keep) {
    forKept(target_, {}, keep,
            [&](const fs::path& rel) { linkTree(target_ / rel, staging_ / rel); });
  }
  fs::path previous;
  if (!had_target) {
    moveNoReplace(staging_, target_, ec);
    if (ec) {
      throw OutputError(target_.string() + ": cannot move the new outputs into place from " +
                        staging_.string() + ": " + ec.message());
    }
  } else {
    hooks_.exchange(staging_, target_, ec);
    if (!ec) {
      previous = staging_;
    } else if (notSupported(ec)) {
      previous = swapWithRenames();
    } else {
      throw OutputError(target_.string() + ": cannot swap in the new outputs from " +
                        staging_.string() + ": " + ec.message() + " (nothing was replaced)");
    }
  }
  committed_ = true;
  if (!previous.empty()) {
    if (keep) {
      keepLateArrivals(previous, keep, notes);
    }
    fs::remove_all(previous, ec);
  }
  return notes;
}

// staging -> ready, target -> old, ready -> target; undone on failure.
fs::path StagedDirectory::swapWithRenames() {
  const fs::path ready = siblingPath(target_, "ready", ::getpid());
  const fs::path old = siblingPath(target_, "old", ::getpid());
  std::error_code ec;
  rename(staging_, ready, ec);
  if (ec) {
    throw OutputError(target_.string() + ": cannot rename the staging folder " + staging_.string() +
                      " to " + ready.string() + ": " + ec.message() + " (nothing was replaced)");
  }
  current_ = ready;
  rename(target_, old, ec);
  if (ec) {
    throw OutputError(target_.string() + ": cannot move the previous outputs aside to " +
                      old.string() + ": " + ec.message() + " (nothing was replaced)");
  }
  rename(ready, target_, ec);
  if (ec) {
    const std::string why = ec.message();
    rename(old, target_, ec);
    throw OutputError(target_.string() + ": cannot move the new outputs into place from " +
                      ready.string() + ": " + why +
                      (ec ? "; the previous outputs are in " + old.string() + ": " + ec.message()
                          : " (nothing was replaced)"));
  }
  return old;
}

void StagedDirectory::keepLateArrivals(const fs::path& previous, const KeepFunction& keep,
                                       std::vector<std::string>& notes) {
  try {
    forKept(previous, {}, keep, [&](const fs::path& rel) {
      std::error_code ec;
      if (!fs::exists(fs::symlink_status(target_ / rel, ec))) {
        linkTree(previous / rel, target_ / rel);
      }
    });
  } catch (const std::exception& e) {
    const fs::path kept = siblingPath(target_, "kept", ::getpid());
    std::error_code ec;
    rename(previous, kept, ec);
    notes.push_back(std::string(e.what()) + "; the previous outputs are kept in " +
                    (ec ? previous : kept).string());
  }
}

std::vector<std::string> StagedDirectory::recover(const fs::path& target) {
  std::vector<std::string> notes;
  std::vector<Leftover> found = leftovers(target);
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(target, ec))) {
    for (const char* kind : {"ready", "old"}) {
      const Leftover* newest = nullptr;
      for (const Leftover& l : found) {
        if (l.kind == kind && (newest == nullptr || l.time > newest->time)) {
          newest = &l;
        }
      }
      if (newest == nullptr) {
        continue;
      }
      fs::rename(newest->path, target, ec);
      if (!ec) {
        notes.push_back(target.string() + ": " +
                        (newest->kind == "ready"
                             ? "finished the swap an interrupted run left: the new outputs "
                             : "restored the previous outputs from ") +
                        newest->path.filename().string());
        break;
      }
    }
  }
  for (const Leftover& l : found) {
    if (fs::exists(l.path, ec)) {
      fs::remove_all(l.path, ec);
      notes.push_back(target.string() + ": removed " + l.path.filename().string() +
                      ", left by a run that did not end cleanly");
    }
  }
  return notes;
}

bool isMountPoint(const fs::path& dir) {
  struct stat self {};
  struct stat parent {};
  if (::stat(dir.c_str(), &self) != 0 || ::stat((dir / "..").c_str(), &parent) != 0) {
    return false;
  }
  if (self.st_dev != parent.st_dev || self.st_ino == parent.st_ino) {
    return true;
  }
  // Bind mounts keep the device of their source: look them up.
  std::ifstream mountinfo("/proc/self/mountinfo");
  std::error_code ec;
  const fs::path canonical = fs::canonical(dir, ec);
  std::string line;
  while (std::getline(mountinfo, line)) {
    std::istringstream fields(line);
    std::string id, parent_id, device, root, mount_point;
    fields >> id >> parent_id >> device >> root >> mount_point;
    std::string decoded;  // octal escapes: \040 is a space
    for (std::size_t i = 0; i < mount_point.size(); ++i) {
      if (mount_point[i] == '\\' && i + 3 < mount_point.size()) {
        decoded.push_back(static_cast<char>(std::stoi(mount_point.substr(i + 1, 3), nullptr, 8)));
        i += 3;
      } else {
        decoded.push_back(mount_point[i]);
      }
    }
    if (!ec && fs::path(decoded) == canonical) {
      return true;
    }
  }
  return false;
}

}  // namespace pmap
