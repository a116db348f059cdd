// The hypotheses as an expert reads them. The fusion expert publishes the
// whole list (HYPOTHESES) only at keyframes and, every tick, what changed
// since (HYPOTHESIS_CHANGES); this port keeps both and answers, like a
// TickInput, with the whole list of a tick:
//
//   expert::HypothesesInput hypotheses_{*this};
//   const hypotheses_t* all = hypotheses_.ofTick(firing.tick);
//
// Logs from before HYPOTHESIS_CHANGES carry HYPOTHESES at every tick: while
// no changes have been heard, the list of tick k is the message of tick k.
#pragma once

#include <cstdint>

#include "lib/expert/keyframed_input.hpp"

namespace beft::expert {

class HypothesesInput
    : public KeyframedInput<hypotheses_t, hypothesis_changes_t, &hypothesis_changes_t::keyframe_tick> {
 public:
  explicit HypothesesInput(Expert& owner, std::size_t capacity = 4)
      : KeyframedInput(owner, channels::kHypotheses, channels::kHypothesisChanges, capacity) {}

  // The whole list of tick k, or null if what makes it has not arrived. The
  // pointer holds until the next call.
  const hypotheses_t* ofTick(int64_t tick) const;
  bool has(int64_t tick) const { return ofTick(tick) != nullptr; }
  // The whole list of the newest tick that can be made, or null.
  const hypotheses_t* latest() const;

  bool lacksTick(int64_t tick) const override { return !empty() && !has(tick - ticksBefore()); }

 private:
  // The list last made: made again only for another tick or keyframe.
  mutable hypotheses_t whole_{};
  mutable int64_t whole_tick_ = -1;
  mutable uint64_t whole_keyframe_sequence_ = 0;
};

}  // namespace beft::expert
