// A lock file with its holder's pid, so that two processes never write the
// same outputs at once, and the one refused can say which process holds them.
//
// The lock is flock(2) on the file: the kernel releases it when its holder
// ends in any way (also SIGKILL), so a lock never outlives its process. The
// file holds the holder's pid as text, for messages only. The holder removes
// the file when it releases the lock (destructor or release()). A file left
// by a holder that could not remove it (SIGKILL, power loss) is taken over
// by the next process, which finds the old pid in it: stalePid().
//
// Works between processes, and between two PidLocks of one process (each
// opens the file anew). Local file systems; NFS only where it emulates flock.
#pragma once

#include <filesystem>

#include "pmap/common/error.h"

namespace pmap {

/// Thrown when another process (or another PidLock) holds the lock.
class LockHeld : public OutputError {
 public:
  LockHeld(const std::string& message, long holder_pid)
      : OutputError(message), holder_pid_(holder_pid) {}
  /// The pid written in the lock file; 0 if not written yet.
  long holderPid() const { return holder_pid_; }

 private:
  long holder_pid_;
};

class PidLock {
 public:
  /// Takes the lock `file`, creating it if needed, and writes this
  /// process's pid into it. Throws LockHeld ("FILE: held by process PID")
  /// if it is held, OutputError naming the file if it cannot be created.
  explicit PidLock(std::filesystem::path file);
  ~PidLock();  ///< release()
  PidLock(const PidLock&) = delete;
  PidLock& operator=(const PidLock&) = delete;

  /// Removes the file and releases the lock (once; later calls do nothing).
  void release();

  /// The pid a previous holder left in the file without releasing it (it
  /// was killed); 0 when the file was new or empty.
  long stalePid() const { return stale_pid_; }
  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  int fd_ = -1;
  long stale_pid_ = 0;
};

}  // namespace pmap
