#include "lib/expert/helper_task.hpp"

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
    lock.unlock();
    yieldUntil([this] { return done_.load(); });  // cpu_placement.hpp: cheaper than a wake-up
    lock.lock();
  }
  changed_.wait(lock, [this] { return done_.load(); });
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
    changed_.notify_all();
  }
}

}  // namespace beft::expert
