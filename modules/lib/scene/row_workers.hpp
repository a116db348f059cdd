// Renders an image's rows on several threads: helper threads kept between
// frames (no thread start per frame) and the caller's, each taking the next
// few rows until none are left, so a helper that wakes late does less
// instead of holding the frame up. A row's pixels depend on nothing outside
// it, so the image is the same whatever the thread count or who took a row.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "lib/common/cpu_placement.hpp"

namespace beft::camera {

class RowWorkers {
 public:
  explicit RowWorkers(int threads);  // 1 or more; threads - 1 helpers
  ~RowWorkers();
  RowWorkers(const RowWorkers&) = delete;
  RowWorkers& operator=(const RowWorkers&) = delete;

  int threads() const { return static_cast<int>(helpers_.size()) + 1; }
  // Runs job(first_row, end_row) over [0, rows) in short runs of rows on
  // the threads, returns when all are done.
  void run(int rows, const std::function<void(int, int)>& job);

 private:
  void helperLoop();
  void claimRows(const std::function<void(int, int)>& job, int rows);

  std::vector<std::thread> helpers_;
  std::mutex mutex_;
  std::condition_variable start_, finished_;
  const std::function<void(int, int)>* job_ = nullptr;
  int rows_ = 0;
  std::atomic<int> working_{0};   // helpers inside the current frame (changed under mutex_, read also without)
  std::atomic<int> next_row_{0};  // first row not yet taken
  uint64_t generation_ = 0;
  bool stop_ = false;
  std::vector<beft::HelperPlacement> placements_;  // one for each helper
};

}  // namespace beft::camera
