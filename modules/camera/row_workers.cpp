#include "row_workers.hpp"

#include <algorithm>

namespace beft::camera {

namespace {
int bandStart(int rows, int band, int bands) {
  return static_cast<int>(static_cast<int64_t>(rows) * band / bands);
}
}  // namespace

RowWorkers::RowWorkers(int threads) {
  for (int band = 1; band < std::max(threads, 1); ++band) helpers_.emplace_back([this, band] { helperLoop(band); });
}

RowWorkers::~RowWorkers() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  start_.notify_all();
  for (auto& helper : helpers_) helper.join();
}

void RowWorkers::run(int rows, const std::function<void(int, int)>& job) {
  const int bands = threads();
  if (bands == 1 || rows < 2 * bands) {
    job(0, rows);
    return;
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    job_ = &job;
    rows_ = rows;
    running_ = bands - 1;
    ++generation_;
  }
  start_.notify_all();
  job(0, bandStart(rows, 1, bands));
  std::unique_lock<std::mutex> lock(mutex_);
  finished_.wait(lock, [this] { return running_ == 0; });
  job_ = nullptr;
}

void RowWorkers::helperLoop(int band) {
  uint64_t seen = 0;
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    start_.wait(lock, [&] { return stop_ || generation_ != seen; });
    if (stop_) return;
    seen = generation_;
    const auto* job = job_;
    const int rows = rows_, bands = threads();
    lock.unlock();
    (*job)(bandStart(rows, band, bands), bandStart(rows, band + 1, bands));
    lock.lock();
    if (--running_ == 0) finished_.notify_all();
  }
}

}  // namespace beft::camera
