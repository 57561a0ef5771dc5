#include "pmap/common/interrupt.h"

#include <signal.h>

#include <atomic>
#include <cassert>
#include <cstdio>

namespace pmap {
namespace {

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
constexpr int kSignalCount = sizeof(kSignals) / sizeof(kSignals[0]);

// The handler touches nothing but this lock-free atomic (async-signal-safe).
static_assert(std::atomic<int>::is_always_lock_free, "the signal flag must be lock-free");
std::atomic<int> g_pending{0};

// Guard state, touched by the main thread only.
bool g_active = false;
bool g_installed[kSignalCount] = {};
struct sigaction g_previous[kSignalCount];

void recordSignal(int signal_number) {
  int none = 0;
  g_pending.compare_exchange_strong(none, signal_number);
}

bool isIgnored(int signal_number) {
  struct sigaction current {};
  ::sigaction(signal_number, nullptr, &current);
  return (current.sa_flags & SA_SIGINFO) == 0 && current.sa_handler == SIG_IGN;
}

}  // namespace

Interrupted::Interrupted(int signal_number)
    : Error(static_cast<ExitCode>(128 + signal_number),
            "interrupted by " + signalName(signal_number)),
      signal_number_(signal_number) {}

InterruptGuard::InterruptGuard() {
  assert(!g_active && "one InterruptGuard at a time");
  g_active = true;
  g_pending.store(0);
  for (int i = 0; i < kSignalCount; ++i) {
    g_installed[i] = !isIgnored(kSignals[i]);
    if (!g_installed[i]) {
      continue;
    }
    struct sigaction action {};
    action.sa_handler = recordSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART | SA_RESETHAND;
    ::sigaction(kSignals[i], &action, &g_previous[i]);
  }
}

InterruptGuard::~InterruptGuard() {
  for (int i = 0; i < kSignalCount; ++i) {
    if (g_installed[i]) {
      ::sigaction(kSignals[i], &g_previous[i], nullptr);
      g_installed[i] = false;
    }
  }
  g_pending.store(0);
  g_active = false;
}

int pendingInterrupt() {
  return g_active ? g_pending.load() : 0;
}

void throwIfInterrupted() {
  if (const int signal_number = pendingInterrupt()) {
    throw Interrupted(signal_number);
  }
}

std::string signalName(int signal_number) {
  switch (signal_number) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
    default:
      return "signal " + std::to_string(signal_number);
  }
}

int reraiseWithDefaultAction(int signal_number) {
  std::fflush(nullptr);
  struct sigaction action {};
  action.sa_handler = SIG_DFL;
  sigemptyset(&action.sa_mask);
  ::sigaction(signal_number, &action, nullptr);
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, signal_number);
  ::pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
  ::raise(signal_number);
  return 128 + signal_number;
}

}  // namespace pmap
