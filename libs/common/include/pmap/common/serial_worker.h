// One thread that runs the jobs it is given one at a time, in the order
// they were given (the loop search's worker, loop_closure.h). With one
// worker, a job never competes with another job for a core, only with the
// thread that submits them; the results come back through futures, so the
// submitter decides when it needs each one.
#pragma once

#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <mutex>
#include <thread>

namespace pmap::common {

template <typename Result>
class SerialWorker {
 public:
  SerialWorker() = default;
  SerialWorker(const SerialWorker&) = delete;
  SerialWorker& operator=(const SerialWorker&) = delete;

  /// Jobs not started yet are dropped (their futures report a broken
  /// promise); a running one is finished. Then the thread is joined.
  ~SerialWorker() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
      queue_.clear();
    }
    wake_.notify_one();
    if (thread_.joinable()) {
      thread_.join();
    }
  }

  /// Queues `job`; the thread starts with the first job. An exception the
  /// job throws is rethrown by the future's get().
  std::future<Result> submit(std::function<Result()> job) {
    std::packaged_task<Result()> task(std::move(job));
    std::future<Result> result = task.get_future();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      queue_.push_back(std::move(task));
      if (!thread_.joinable()) {
        thread_ = std::thread([this] { run(); });
      }
    }
    wake_.notify_one();
    return result;
  }

 private:
  void run() {
    for (;;) {
      std::packaged_task<Result()> task;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [this] { return stop_ || !queue_.empty(); });
        if (stop_) {
          return;
        }
        task = std::move(queue_.front());
        queue_.pop_front();
      }
      task();  // stores the result or the exception in the future
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::packaged_task<Result()>> queue_;
  bool stop_ = false;
  std::thread thread_;  ///< started by the first submit(), joined by the destructor
};

}  // namespace pmap::common
