#include "lib/scene/row_workers.hpp"

#include <algorithm>

namespace beft::camera {

namespace {
constexpr int kRowsPerClaim = 4;  // a few microseconds of work: the last claim ends soon after the others
}  // namespace

RowWorkers::RowWorkers(int threads) : placements_(static_cast<std::size_t>(std::max(threads, 1) - 1)) {
  for (int helper = 1; helper < std::max(threads, 1); ++helper) helpers_.emplace_back([this] { helperLoop(); });
}

RowWorkers::~RowWorkers() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  start_.notify_all();
  for (auto& helper : helpers_) helper.join();
}

void RowWorkers::claimRows(const std::function<void(int, int)>& job, int rows) {
  for (;;) {
    const int first = next_row_.fetch_add(kRowsPerClaim, std::memory_order_relaxed);
    if (first >= rows) return;
    job(first, std::min(first + kRowsPerClaim, rows));
  }
}

void RowWorkers::run(int rows, const std::function<void(int, int)>& job) {
  if (helpers_.empty() || rows < 2 * kRowsPerClaim) {
    job(0, rows);
    return;
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    job_ = &job;
    rows_ = rows;
    next_row_.store(0, std::memory_order_relaxed);
    ++generation_;
  }
  // Off the caller's CPU, so that they work side by side (cpu_placement.hpp).
  for (std::size_t i = 0; i < helpers_.size(); ++i) placements_[i].keepOffMyCpu(helpers_[i].native_handle());
  start_.notify_all();
  // The caller works from the start: a helper that wakes late takes fewer
  // rows, or none, instead of holding the frame up.
  claimRows(job, rows);
  std::unique_lock<std::mutex> lock(mutex_);
  job_ = nullptr;  // a helper waking from now on takes nothing
  if (working_ > 0) {
    // A helper is on its last claim, a few microseconds: cheaper to wait on
    // the CPU than to sleep and be woken (cpu_placement.hpp).
    lock.unlock();
    yieldUntil([this] { return working_.load() == 0; });
    lock.lock();
  }
  finished_.wait(lock, [this] { return working_.load() == 0; });
}

void RowWorkers::helperLoop() {
  uint64_t seen = 0;
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    start_.wait(lock, [&] { return stop_ || generation_ != seen; });
    if (stop_) return;
    seen = generation_;
    if (job_ == nullptr) continue;  // woke after the frame was done
    const auto* job = job_;
    const int rows = rows_;
    ++working_;
    lock.unlock();
    claimRows(*job, rows);
    lock.lock();
    if (--working_ == 0) finished_.notify_all();
  }
}

}  // namespace beft::camera
