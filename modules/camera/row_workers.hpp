// Splits an image's rows into bands and renders them at once on several
// threads: helper threads kept between frames (no thread start per frame),
// the first band on the caller's thread. Each band's pixels depend on nothing
// outside the band, so the image is the same whatever the thread count.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace beft::camera {

class RowWorkers {
 public:
  explicit RowWorkers(int threads);  // 1 or more; threads - 1 helpers
  ~RowWorkers();
  RowWorkers(const RowWorkers&) = delete;
  RowWorkers& operator=(const RowWorkers&) = delete;

  int threads() const { return static_cast<int>(helpers_.size()) + 1; }
  // Runs job(first_row, end_row) on threads() bands of [0, rows), returns when all are done.
  void run(int rows, const std::function<void(int, int)>& job);

 private:
  void helperLoop(int band);

  std::vector<std::thread> helpers_;
  std::mutex mutex_;
  std::condition_variable start_, finished_;
  const std::function<void(int, int)>* job_ = nullptr;
  int rows_ = 0, running_ = 0;
  uint64_t generation_ = 0;
  bool stop_ = false;
};

}  // namespace beft::camera
