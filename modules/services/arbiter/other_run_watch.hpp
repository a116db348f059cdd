// Another run on this arbiter's LCM URL (a user who shares a URL by mistake):
// every arbiter sends a beacon on BEFT_RUNS twice a second, and an arbiter
// that hears another run's says so within a second, in both runs. Neither
// takes the other's messages (run_identity.hpp); this says why the URL is busy.
#pragma once

#include <chrono>
#include <cstdint>
#include <set>
#include <string>

namespace beft::arbiter {

class OtherRunWatch {
 public:
  using Clock = std::chrono::steady_clock;
  // Another run's beacon; an error line for a new run at once, else at most every 10 s.
  void heard(int64_t run_id, const std::string& host, int pid, Clock::time_point now = Clock::now());
  const std::set<int64_t>& runsHeard() const { return runs_; }

 private:
  std::set<int64_t> runs_;
  Clock::time_point last_report_;
};

}  // namespace beft::arbiter
