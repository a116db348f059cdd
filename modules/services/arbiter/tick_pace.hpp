// When a tick may start: at once (fast, the default), or in real time, not
// before its simulated time has passed on the wall clock since the run, or
// its last resume, began; for a person watching. Only the start of a tick
// waits, never a firing: what the run computes does not change.
#pragma once

#include <cstdint>
#include <string>

namespace beft::arbiter {

enum class Pace { kFast, kRealTime };

// "fast" or "real-time"; std::invalid_argument naming both otherwise.
Pace parsePace(const std::string& text);
const char* paceName(Pace pace);

class TickPace {
 public:
  TickPace(Pace pace, double dt_s) : pace_(pace), dt_s_(dt_s) {}
  // Tick `tick` starts at wall time `now_s` (the run began, or resumed).
  void restart(double now_s, int64_t tick) {
    origin_s_ = now_s;
    origin_tick_ = tick;
  }
  // The earliest wall time tick `tick` may start; -inf when fast.
  double earliestStart(int64_t tick) const;
  Pace pace() const { return pace_; }

 private:
  Pace pace_;
  double dt_s_;
  double origin_s_ = 0.0;
  int64_t origin_tick_ = 0;
};

}  // namespace beft::arbiter
