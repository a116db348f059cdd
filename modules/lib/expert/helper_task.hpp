// One job at a time on a helper thread kept for the process's life, so that
// an expert can do two independent parts of a firing at once (no thread is
// started per firing). wait() returns when the job is done and throws what it
// threw. The job must not touch what the caller changes until wait() returns.
#pragma once

#include <atomic>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

#include "lib/common/cpu_placement.hpp"

namespace beft::expert {

class HelperTask {
 public:
  HelperTask();
  ~HelperTask();  // waits for a running job, then ends the thread
  HelperTask(const HelperTask&) = delete;
  HelperTask& operator=(const HelperTask&) = delete;

  // Starts job on the helper thread. Throws std::logic_error if the last job
  // has not been waited for.
  void start(std::function<void()> job);
  // Waits for the job started last and rethrows its exception, if any.
  // Returns at once when no job was started.
  void wait();

 private:
  void loop();

  std::mutex mutex_;
  std::condition_variable changed_;
  std::function<void()> job_;
  std::exception_ptr error_;
  bool running_ = false;  // started and not yet waited for
  std::atomic<bool> done_{false};  // the job started last has finished (set under mutex_, read also without)
  bool stop_ = false;
  HelperPlacement placement_;
  std::thread thread_;  // last: starts once the rest is set up
};

// Waits for a HelperTask when leaving a scope, also by an exception (whose
// own exception is then dropped: the first one is the one to report).
class WaitOnExit {
 public:
  explicit WaitOnExit(HelperTask& task) : task_(task) {}
  ~WaitOnExit() {
    try {
      task_.wait();
    } catch (...) {
    }
  }
  WaitOnExit(const WaitOnExit&) = delete;
  WaitOnExit& operator=(const WaitOnExit&) = delete;

 private:
  HelperTask& task_;
};

}  // namespace beft::expert
