// Whether the next tick may start, as viewers and tools asked on
// RUN_CONTROL: run on, pause (finish the current tick, then hold) or step
// (run until a given tick has finished, then hold). A request carries the
// whole desired state and is applied once per (origin, sequence): a resent
// or older request of the same origin changes nothing. No LCM, no clock.
#pragma once

#include <beft/run_control_t.hpp>

#include <cstdint>
#include <map>
#include <string>

namespace beft::arbiter {

class RunControl {
 public:
  enum class Outcome {
    kApplied,   // a new desired state
    kRepeated,  // the request last applied for its origin, sent again
    kOld,       // an older sequence of its origin: changes nothing
    kRefused,   // not a valid request (why: refusal())
  };

  // Applies `request` with the arbiter at `tick` (the tick running, or the
  // one finished while holding): a pause holds after that tick, a step to a
  // tick already finished too.
  Outcome apply(const beft::run_control_t& request, int64_t tick);
  // After a restart: the state last answered (RUN_CONTROL_STATE in the
  // run's log) taken up again, its request counted as applied.
  void restore(const beft::run_control_t& state);
  // Why the last request was refused.
  const std::string& refusal() const { return refusal_; }

  // Whether the tick after `finished_tick` must wait.
  bool holdsAfter(int64_t finished_tick) const { return holding_ && finished_tick >= hold_after_tick_; }
  bool holding() const { return holding_; }
  int64_t holdAfterTick() const { return hold_after_tick_; }
  int8_t requestedMode() const { return requested_mode_; }
  const std::string& origin() const { return origin_; }
  int64_t sequence() const { return sequence_; }

  // The answer on RUN_CONTROL_STATE (utime left 0): MODE_PAUSE while held
  // after `tick`, MODE_STEP while running towards the hold, MODE_RUN when no
  // hold is asked for; the request last applied.
  beft::run_control_t state(int64_t tick, bool held) const;
  // The same, answering a request of `origin` sent again or outdated: it
  // names the sequence last applied for that origin (so a requester whose
  // request was applied before another origin's learns it was heard, and
  // one that numbers from too low learns where to go on).
  beft::run_control_t answerTo(const std::string& origin, int64_t tick, bool held) const;

  // Origins remembered; the oldest is forgotten beyond it.
  static constexpr std::size_t kMaxOrigins = 64;
  static constexpr std::size_t kMaxOriginLength = 64;

 private:
  std::string invalidBecause(const beft::run_control_t& request) const;

  bool holding_ = false;
  int64_t hold_after_tick_ = 0;
  int8_t requested_mode_ = beft::run_control_t::MODE_RUN;
  std::string origin_;
  int64_t sequence_ = 0;
  std::string refusal_;
  std::map<std::string, int64_t> applied_;  // per origin, the sequence last applied
  std::map<std::string, int64_t> order_;    // per origin, when it was last applied (to forget the oldest)
  int64_t applications_ = 0;
};

}  // namespace beft::arbiter
