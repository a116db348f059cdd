#include "helper_task.hpp"

#include <sched.h>

#include <chrono>
#include <stdexcept>
#include <utility>

namespace beft::expert {

HelperTask::HelperTask() : thread_([this] { loop(); }) {}

HelperTask::~HelperTask() {
  {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [this] { return !running_ || done_; });
    stop_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void HelperTask::start(std::function<void()> job) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (running_) throw std::logic_error("HelperTask::start: the last job was not waited for");
    job_ = std::move(job);
    error_ = nullptr;
    running_ = true;
    done_ = false;
  }
  placement_.keepOffMyCpu(thread_.native_handle());  // so that the job runs beside the caller
  changed_.notify_all();
}

void HelperTask::wait() {
  std::unique_lock<std::mutex> lock(mutex_);
  if (!running_) return;
  if (!done_) {
    // Stay on the CPU for a while rather than sleep: waking a sleeping thread
    // takes tens of microseconds on a virtual machine, which is a good part
    // of the job. Yielding lets any other thread ready here run meanwhile.
    lock.unlock();
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::milliseconds(2);
    while (!finished_.load(std::memory_order_acquire) && std::chrono::steady_clock::now() < give_up) sched_yield();
    lock.lock();
  }
  changed_.wait(lock, [this] { return done_; });
  finished_.store(false, std::memory_order_relaxed);
  running_ = false;
  job_ = nullptr;
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
}

void HelperTask::loop() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    changed_.wait(lock, [this] { return stop_ || (running_ && !done_); });
    if (stop_) return;
    lock.unlock();
    std::exception_ptr error;
    try {
      job_();
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    error_ = error;
    done_ = true;
    finished_.store(true, std::memory_order_release);
    changed_.notify_all();
  }
}

}  // namespace beft::expert
