// An orderly stop on SIGINT, SIGTERM and SIGHUP, so that a run can remove its
// temporary files instead of dying with them on disk.
//
// While an InterruptGuard lives, these signals only record their number (the
// handler does nothing else, so it is async-signal-safe). The program polls at
// safe points with throwIfInterrupted(), which throws Interrupted; the stack
// unwinds and the destructors of the temporary outputs remove them. main()
// catches Interrupted, prints one line and calls reraiseWithDefaultAction(),
// so the process ends by the same signal (the shell reports 128 + signo: 130
// for SIGINT, 143 for SIGTERM) and a calling shell script stops as it would
// for any program killed by Ctrl-C.
//
//   int main() {
//     try {
//       pmap::InterruptGuard guard;          // around the part that writes
//       for (...) { pmap::throwIfInterrupted(); work(); }
//     } catch (const pmap::Interrupted& e) {
//       std::cerr << "app: " << e.what() << "\n";
//       return pmap::reraiseWithDefaultAction(e.signalNumber());
//     }
//   }
//
// Details:
//  - a signal whose disposition is SIG_IGN when the guard is made (nohup, a
//    background job of a non-interactive shell) stays ignored;
//  - the handler is installed with SA_RESETHAND: a second signal of the same
//    kind takes the default action at once (ends the process, temporaries may
//    then remain): the way out if cleaning up ever hangs;
//  - the destructor restores the previous dispositions and forgets a pending
//    signal (one that arrived after the last poll, e.g. during a commit);
//  - one guard at a time, made and destroyed on the main thread; signals may be
//    delivered to any thread.
#pragma once

#include <string>

#include "pmap/common/error.h"

namespace pmap {

/// Thrown by throwIfInterrupted(). exitCode() is 128 + the signal number.
class Interrupted : public Error {
 public:
  explicit Interrupted(int signal_number);
  int signalNumber() const { return signal_number_; }

 private:
  int signal_number_;
};

class InterruptGuard {
 public:
  InterruptGuard();   ///< installs the handlers; asserts no other guard is alive
  ~InterruptGuard();  ///< restores the previous dispositions
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
};

/// The first signal received while the current guard lives; 0 if none or no guard.
int pendingInterrupt();

/// Throws Interrupted if pendingInterrupt() != 0.
void throwIfInterrupted();

/// "SIGINT", "SIGTERM", "SIGHUP", otherwise "signal N".
std::string signalName(int signal_number);

/// Restores the default action of `signal_number`, unblocks and raises it: the
/// process normally ends here, by that signal. Returns 128 + signal_number in
/// case it does not (for `return` from main).
int reraiseWithDefaultAction(int signal_number);

}  // namespace pmap
