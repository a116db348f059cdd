#include "lib/service/run_control_client.hpp"

#include <algorithm>
#include <utility>

namespace beft::service {

RunControlClient::RunControlClient(std::string origin, int64_t first_sequence)
    : origin_(std::move(origin)), next_sequence_(std::max<int64_t>(0, first_sequence)) {}

void RunControlClient::request(int8_t mode, int64_t hold_after_tick) {
  beft::run_control_t wanted{};
  wanted.sequence = next_sequence_++;
  wanted.mode = mode;
  wanted.hold_after_tick = mode == beft::run_control_t::MODE_STEP ? hold_after_tick : 0;
  wanted.origin = origin_;
  desired_ = wanted;
  acknowledged_ = false;
  last_sent_us_.reset();
}

void RunControlClient::stepOne() {
  int64_t last_known = last_state_ ? last_state_->tick : -1;
  // A step asked for and not reached yet counts as known: a second step goes one further.
  const bool step_under_way =
      desired_ && desired_->mode == beft::run_control_t::MODE_STEP &&
      (!acknowledged_ || (last_state_ && last_state_->mode == beft::run_control_t::MODE_STEP));
  if (step_under_way) last_known = std::max(last_known, desired_->hold_after_tick);
  request(beft::run_control_t::MODE_STEP, last_known + 1);
}

void RunControlClient::onState(const beft::run_control_t& state) {
  last_state_ = state;
  if (!desired_ || acknowledged_ || state.origin != origin_) return;
  if (state.sequence == desired_->sequence) {
    acknowledged_ = true;
  } else if (state.sequence > desired_->sequence) {
    // The arbiter applied a later request of this origin (from before a
    // restart of this requester): this one would be ignored. Renumbered, and sent at once.
    desired_->sequence = state.sequence + 1;
    next_sequence_ = desired_->sequence + 1;
    last_sent_us_.reset();
  }
}

std::optional<beft::run_control_t> RunControlClient::due(int64_t now_us) {
  if (!desired_ || acknowledged_) return std::nullopt;
  if (last_sent_us_ && now_us - *last_sent_us_ < kResendInterval_us) return std::nullopt;
  last_sent_us_ = now_us;
  beft::run_control_t request = *desired_;
  request.utime = now_us;
  return request;
}

const char* runControlModeName(int8_t mode) {
  switch (mode) {
    case beft::run_control_t::MODE_RUN: return "run";
    case beft::run_control_t::MODE_PAUSE: return "pause";
    case beft::run_control_t::MODE_STEP: return "step";
  }
  return "unknown";
}

std::string describeRunControlState(const beft::run_control_t& state) {
  const std::string at = " (at tick " + std::to_string(state.tick) + ")";
  switch (state.mode) {
    case beft::run_control_t::MODE_PAUSE: return "paused after tick " + std::to_string(state.tick);
    case beft::run_control_t::MODE_STEP: return "stepping: holds after tick " + std::to_string(state.hold_after_tick) + at;
    case beft::run_control_t::MODE_RUN: return "running" + at;
  }
  return "mode " + std::to_string(state.mode) + at;
}

}  // namespace beft::service
