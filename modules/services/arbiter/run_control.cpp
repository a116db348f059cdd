#include "services/arbiter/run_control.hpp"

#include <algorithm>

namespace beft::arbiter {

std::string RunControl::invalidBecause(const beft::run_control_t& request) const {
  const int8_t mode = request.mode;
  if (mode != beft::run_control_t::MODE_RUN && mode != beft::run_control_t::MODE_PAUSE &&
      mode != beft::run_control_t::MODE_STEP)
    return "unknown mode " + std::to_string(mode);
  if (request.sequence < 0) return "negative sequence " + std::to_string(request.sequence);
  if (mode == beft::run_control_t::MODE_STEP && request.hold_after_tick < 0)
    return "negative hold_after_tick " + std::to_string(request.hold_after_tick);
  if (request.origin.empty()) return "no origin";
  if (request.origin.size() > kMaxOriginLength)
    return "an origin longer than " + std::to_string(kMaxOriginLength) + " characters";
  return "";
}

RunControl::Outcome RunControl::apply(const beft::run_control_t& request, int64_t tick) {
  refusal_ = invalidBecause(request);
  if (!refusal_.empty()) return Outcome::kRefused;
  const auto applied = applied_.find(request.origin);
  if (applied != applied_.end() && request.sequence <= applied->second)
    return request.sequence == applied->second ? Outcome::kRepeated : Outcome::kOld;
  if (applied == applied_.end() && applied_.size() >= kMaxOrigins) {
    const auto oldest = std::min_element(order_.begin(), order_.end(),
                                         [](const auto& a, const auto& b) { return a.second < b.second; });
    applied_.erase(oldest->first);
    order_.erase(oldest);
  }
  applied_[request.origin] = request.sequence;
  order_[request.origin] = ++applications_;
  origin_ = request.origin;
  sequence_ = request.sequence;
  requested_mode_ = request.mode;
  holding_ = request.mode != beft::run_control_t::MODE_RUN;
  // A pause finishes the tick under way; a step to a tick already finished
  // holds as soon as the current one has.
  hold_after_tick_ = request.mode == beft::run_control_t::MODE_STEP ? std::max(request.hold_after_tick, tick) : tick;
  if (!holding_) hold_after_tick_ = 0;
  return Outcome::kApplied;
}

void RunControl::restore(const beft::run_control_t& state) {
  if (!invalidBecause(state).empty()) return;
  applied_[state.origin] = state.sequence;
  order_[state.origin] = ++applications_;
  origin_ = state.origin;
  sequence_ = state.sequence;
  requested_mode_ = state.mode;
  holding_ = state.mode != beft::run_control_t::MODE_RUN;
  // Held: after the tick it held after; on the way to a hold: where it was going.
  hold_after_tick_ = state.mode == beft::run_control_t::MODE_PAUSE  ? state.tick
                     : state.mode == beft::run_control_t::MODE_STEP ? state.hold_after_tick
                                                                    : 0;
}

beft::run_control_t RunControl::state(int64_t tick, bool held) const {
  beft::run_control_t state{};
  state.utime = 0;
  state.sequence = sequence_;
  state.mode = held       ? beft::run_control_t::MODE_PAUSE
               : holding_ ? beft::run_control_t::MODE_STEP
                          : beft::run_control_t::MODE_RUN;
  state.hold_after_tick = holding_ ? hold_after_tick_ : 0;
  state.tick = tick;
  state.origin = origin_;
  return state;
}

beft::run_control_t RunControl::answerTo(const std::string& origin, int64_t tick, bool held) const {
  beft::run_control_t answer = state(tick, held);
  const auto applied = applied_.find(origin);
  if (applied == applied_.end()) return answer;
  answer.origin = origin;
  answer.sequence = applied->second;
  return answer;
}

}  // namespace beft::arbiter
