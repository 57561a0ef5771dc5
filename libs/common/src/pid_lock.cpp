#include "pmap/common/pid_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>

namespace pmap {
namespace {

long readPid(int fd) {
  char text[32] = {};
  const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
  if (n <= 0) {
    return 0;
  }
  char* end = nullptr;
  const long pid = std::strtol(text, &end, 10);
  return end != text && pid > 0 ? pid : 0;
}

/// True when `fd` is still the file at `path` (not removed or replaced by a
/// holder that released the lock between our open() and flock()).
bool stillThere(int fd, const std::filesystem::path& path) {
  struct stat open_file {};
  struct stat named {};
  return ::fstat(fd, &open_file) == 0 && ::stat(path.c_str(), &named) == 0 &&
         open_file.st_dev == named.st_dev && open_file.st_ino == named.st_ino;
}

std::string errnoText() {
  return std::strerror(errno);
}

}  // namespace

PidLock::PidLock(std::filesystem::path file) : file_(std::move(file)) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int fd = ::open(file_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) {
      throw OutputError(file_.string() + ": cannot create the lock file: " + errnoText());
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      long holder = readPid(fd);
      for (int wait = 0; holder == 0 && error == EWOULDBLOCK && wait < 50; ++wait) {
        ::usleep(2000);  // the holder writes its pid right after it took the lock
        holder = readPid(fd);
      }
      ::close(fd);
      if (error == EWOULDBLOCK) {
        throw LockHeld(file_.string() + ": held by " +
                           (holder > 0 ? "process " + std::to_string(holder)
                                       : std::string("another process (pid not written yet)")),
                       holder);
      }
      throw OutputError(file_.string() + ": cannot lock: " + std::strerror(error));
    }
    if (!stillThere(fd, file_)) {
      ::close(fd);  // released and removed meanwhile: lock the new file
      continue;
    }
    stale_pid_ = readPid(fd);
    const std::string pid = std::to_string(::getpid()) + "\n";
    if (::ftruncate(fd, 0) != 0 ||
        ::pwrite(fd, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size())) {
      const std::string why = errnoText();
      ::unlink(file_.c_str());
      ::close(fd);
      throw OutputError(file_.string() + ": cannot write the lock file: " + why);
    }
    fd_ = fd;
    return;
  }
  throw OutputError(file_.string() + ": cannot lock: the file keeps being replaced");
}

PidLock::~PidLock() {
  release();
}

void PidLock::release() {
  if (fd_ < 0) {
    return;
  }
  // Removed while still locked: a process that opened it meanwhile finds,
  // once it gets the lock, that it is no longer the file and starts over.
  ::unlink(file_.c_str());
  ::close(fd_);
  fd_ = -1;
}

}  // namespace pmap
