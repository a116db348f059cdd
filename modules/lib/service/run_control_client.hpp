// The requesting side of RUN_CONTROL (pause, step, run on), for viewers and
// tools: it keeps the desired state, numbers it, says when to send it
// (again) and recognises the arbiter's answer on RUN_CONTROL_STATE. No LCM
// inside: the caller publishes what due() returns and feeds onState() what
// it receives.
//
//   RunControlClient control("viewer");
//   control.request(run_control_t::MODE_PAUSE, 0);
//   ... in the loop:
//   if (auto request = control.due(wallMicros())) publish RUN_CONTROL, *request
//   on RUN_CONTROL_STATE: control.onState(state)
//
// What the arbiter answers (and lastState() holds): mode MODE_PAUSE while it
// holds after `tick` (that tick finished, the next waits), MODE_STEP while it
// runs towards its hold after `hold_after_tick` (a pause included, which
// holds after the tick it came in), MODE_RUN when nothing holds it; `tick`
// is the tick it is at; `origin` and `sequence` name the request it applied
// last. It applies a request once per (origin, sequence), so each requester
// needs an origin of its own.
#pragma once

#include <beft/run_control_t.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace beft::service {

class RunControlClient {
 public:
  // Requests re-sent this often until answered.
  static constexpr int64_t kResendInterval_us = 100000;

  // `first_sequence`: a requester that may be started again while the run
  // goes on (a command-line tool) passes one above any it used before, e.g.
  // the wall clock in microseconds; an older one would be ignored until the
  // arbiter's answer names this origin (then it is renumbered).
  explicit RunControlClient(std::string origin, int64_t first_sequence = 1);

  // The desired state, with the next sequence: mode MODE_RUN, MODE_PAUSE or
  // MODE_STEP (hold after tick `hold_after_tick` has finished).
  void request(int8_t mode, int64_t hold_after_tick);
  // Hold after the tick after the last one known: the tick the arbiter
  // said it is at, or the step asked for and not reached yet. Pressed
  // twice, it steps twice.
  void stepOne();

  // The arbiter has answered the desired state last set (true when none is set).
  bool acknowledged() const { return acknowledged_; }
  // The arbiter's last answer, if any arrived.
  std::optional<beft::run_control_t> lastState() const { return last_state_; }
  // The desired state last set, if any.
  std::optional<beft::run_control_t> desired() const { return desired_; }
  const std::string& origin() const { return origin_; }

  // An answer from RUN_CONTROL_STATE.
  void onState(const beft::run_control_t& state);
  // The request to send now: the desired state while it is not answered,
  // at once after request() and then every kResendInterval_us; utime = now_us.
  std::optional<beft::run_control_t> due(int64_t now_us);

 private:
  std::string origin_;
  int64_t next_sequence_;
  std::optional<beft::run_control_t> desired_;
  std::optional<beft::run_control_t> last_state_;
  std::optional<int64_t> last_sent_us_;
  bool acknowledged_ = true;
};

// "run", "pause", "step"; "unknown" for any other value.
const char* runControlModeName(int8_t mode);
// One line for people: "paused after tick 12", "stepping: holds after tick
// 15 (at tick 13)", "running (at tick 40)".
std::string describeRunControlState(const beft::run_control_t& state);

}  // namespace beft::service
