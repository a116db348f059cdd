#include "lib/expert/hypotheses_input.hpp"

#include "lib/wire/hypothesis_changes.hpp"

namespace beft::expert {

const hypotheses_t* HypothesesInput::ofTick(int64_t tick) const {
  const Parts parts = partsOfTick(tick);
  if (parts.keyframe == nullptr) return nullptr;
  const auto& keyframe = *parts.keyframe;
  if (keyframe.message.tick == tick) return &keyframe.message;
  if (whole_tick_ != tick || whole_keyframe_sequence_ != keyframe.sequence) {
    if (!wire::applyChanges(keyframe.message, *parts.per_tick, whole_)) return nullptr;
    whole_tick_ = tick;
    whole_keyframe_sequence_ = keyframe.sequence;
  }
  return &whole_;
}

const hypotheses_t* HypothesesInput::latest() const {
  if (const hypothesis_changes_t* newest = newestPerTick())
    if (const hypotheses_t* whole = ofTick(newest->tick)) return whole;
  const Entry* keyframe = newestKeyframe();
  return keyframe == nullptr ? nullptr : &keyframe->message;
}

}  // namespace beft::expert
