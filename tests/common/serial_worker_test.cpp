// SerialWorker: one thread, jobs in submission order, exceptions through
// the futures, and a destructor that neither hangs nor leaves a thread.
#include "pmap/common/serial_worker.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <future>
#include <stdexcept>
#include <thread>
#include <vector>

namespace pmap::common {
namespace {

TEST(SerialWorker, RunsJobsOneAtATimeInTheOrderGiven) {
  SerialWorker<int> worker;
  std::vector<int> order;  // touched by the worker's thread only, read after get()
  int running = 0, most_at_once = 0;
  std::vector<std::future<int>> results;
  for (int i = 0; i < 50; ++i) {
    results.push_back(worker.submit([&, i] {
      most_at_once = std::max(most_at_once, ++running);
      order.push_back(i);
      --running;
      return 2 * i;
    }));
  }
  for (int i = 0; i < 50; ++i) {
    EXPECT_EQ(results[static_cast<std::size_t>(i)].get(), 2 * i);
  }
  ASSERT_EQ(order.size(), 50u);
  for (int i = 0; i < 50; ++i) {
    EXPECT_EQ(order[static_cast<std::size_t>(i)], i);
  }
  EXPECT_EQ(most_at_once, 1);
}

TEST(SerialWorker, AJobsExceptionComesBackThroughItsFuture) {
  SerialWorker<int> worker;
  auto bad = worker.submit([]() -> int { throw std::runtime_error("no match"); });
  auto good = worker.submit([] { return 7; });
  EXPECT_THROW(bad.get(), std::runtime_error);
  EXPECT_EQ(good.get(), 7);  // the thread goes on after a job that threw
}

// Destroyed while jobs wait (the first one, if it started, blocked until
// another thread opens a gate): a started job finishes, the others are done
// or dropped (a broken promise); nothing hangs.
TEST(SerialWorker, DestroyedWithQueuedJobsReturns) {
  std::promise<void> gate;
  std::shared_future<void> open = gate.get_future().share();
  std::vector<std::future<int>> results;
  std::thread opener;
  {
    SerialWorker<int> worker;
    results.push_back(worker.submit([open] {
      open.wait();
      return 1;
    }));
    for (int i = 2; i <= 4; ++i) {
      results.push_back(worker.submit([i] { return i; }));
    }
    opener = std::thread([&gate] { gate.set_value(); });
  }
  opener.join();
  for (std::size_t i = 0; i < results.size(); ++i) {
    try {
      EXPECT_EQ(results[i].get(), static_cast<int>(i) + 1);
    } catch (const std::future_error& e) {
      EXPECT_EQ(e.code(), std::future_errc::broken_promise);
    }
  }
}

TEST(SerialWorker, AnUnusedWorkerStartsNoThread) {
  SerialWorker<int> worker;  // destroyed at once: nothing to join
  SUCCEED();
}

}  // namespace
}  // namespace pmap::common
