#include "pmap/common/interrupt.h"

#include <gtest/gtest.h>
#include <signal.h>

#include <cstdlib>
#include <string>

namespace pmap {
namespace {

void (*currentHandler(int signal_number))(int) {
  struct sigaction current {};
  ::sigaction(signal_number, nullptr, &current);
  return current.sa_handler;
}

void customHandler(int) {}

/// The default actions, whatever the test runner's parent ignored (a
/// background job of a script ignores SIGINT; nohup ignores SIGHUP).
void defaultDispositions() {
  for (const int s : {SIGINT, SIGTERM, SIGHUP}) {
    ::signal(s, SIG_DFL);
  }
}

TEST(Interrupt, Item12_SignalUnderAGuardIsRecordedNotFatal) {
  defaultDispositions();
  InterruptGuard guard;
  EXPECT_EQ(pendingInterrupt(), 0);
  EXPECT_NO_THROW(throwIfInterrupted());
  ::raise(SIGTERM);
  EXPECT_EQ(pendingInterrupt(), SIGTERM);
  try {
    throwIfInterrupted();
    FAIL() << "no Interrupted thrown";
  } catch (const Interrupted& e) {
    EXPECT_EQ(e.signalNumber(), SIGTERM);
    EXPECT_EQ(e.exitCode(), 128 + SIGTERM);
    EXPECT_EQ(std::string(e.what()), "interrupted by SIGTERM");
  }
}

TEST(Interrupt, Item12_TheFirstSignalWins) {
  defaultDispositions();
  InterruptGuard guard;
  ::raise(SIGINT);
  ::raise(SIGHUP);
  EXPECT_EQ(pendingInterrupt(), SIGINT);
}

TEST(Interrupt, Item12_GuardRestoresThePreviousDispositionsAndForgetsThePendingSignal) {
  defaultDispositions();
  ::signal(SIGINT, customHandler);
  ::signal(SIGTERM, SIG_DFL);
  {
    InterruptGuard guard;
    EXPECT_NE(currentHandler(SIGINT), customHandler);
    EXPECT_NE(currentHandler(SIGTERM), SIG_DFL);
    ::raise(SIGINT);
    EXPECT_EQ(pendingInterrupt(), SIGINT);
  }
  EXPECT_EQ(currentHandler(SIGINT), customHandler);
  EXPECT_EQ(currentHandler(SIGTERM), SIG_DFL);
  EXPECT_EQ(pendingInterrupt(), 0);
  EXPECT_NO_THROW(throwIfInterrupted());
  ::signal(SIGINT, SIG_DFL);
}

TEST(Interrupt, Item12_IgnoredSignalsStayIgnored) {
  defaultDispositions();
  ::signal(SIGHUP, SIG_IGN);  // as under nohup
  {
    InterruptGuard guard;
    EXPECT_EQ(currentHandler(SIGHUP), SIG_IGN);
    ::raise(SIGHUP);
    EXPECT_EQ(pendingInterrupt(), 0);
  }
  EXPECT_EQ(currentHandler(SIGHUP), SIG_IGN);
  ::signal(SIGHUP, SIG_DFL);
}

TEST(Interrupt, Item12_ASecondSignalTakesTheDefaultAction) {
  EXPECT_EXIT(
      {
        defaultDispositions();
        InterruptGuard guard;
        ::raise(SIGTERM);
        ::raise(SIGTERM);
        std::exit(0);
      },
      ::testing::KilledBySignal(SIGTERM), "");
}

TEST(Interrupt, Item12_ReraiseEndsTheProcessByTheSignal) {
  EXPECT_EXIT(
      {
        defaultDispositions();
        int signal_number = 0;
        {
          InterruptGuard guard;
          ::raise(SIGINT);
          signal_number = pendingInterrupt();
        }
        reraiseWithDefaultAction(signal_number);
        std::exit(0);
      },
      ::testing::KilledBySignal(SIGINT), "");
}

TEST(Interrupt, SignalNames) {
  EXPECT_EQ(signalName(SIGINT), "SIGINT");
  EXPECT_EQ(signalName(SIGHUP), "SIGHUP");
  EXPECT_EQ(signalName(SIGUSR1), "signal " + std::to_string(SIGUSR1));
}

}  // namespace
}  // namespace pmap
