#include "hypotheses_input.hpp"

#include "hypothesis_changes.hpp"

namespace beft::expert {

HypothesesInput::HypothesesInput(Expert& owner, std::size_t capacity)
    : InputPortBase(owner, channels::kHypotheses.name, channels::kHypotheses.typeName()),
      keyframes_(capacity),
      changes_(owner, channels::kHypothesisChanges, 16, {}, /*optional_until_heard=*/true) {}

bool HypothesesInput::receive(const void* data, int size) {
  hypotheses_t message{};
  if (!decodeMessage(channel(), data, size, message)) return false;
  const int64_t utime = message.utime;
  keyframes_.store(std::move(message), utime);
  return true;
}

const blackboard::ChannelHistory<hypotheses_t>::Entry* HypothesesInput::keyframeOfTick(int64_t tick) const {
  for (const auto* entry = keyframes_.latest(); entry != nullptr; entry = keyframes_.atOrBefore(entry->utime - 1))
    if (entry->message.tick == tick) return entry;
  return nullptr;
}

const hypotheses_t* HypothesesInput::ofTick(int64_t tick) const {
  const hypothesis_changes_t* changes = changes_.ofTick(tick);
  // No changes for this tick: a whole list of the tick itself holds (a
  // keyframe, or a log from before the changes).
  const auto* keyframe = keyframeOfTick(changes != nullptr ? changes->keyframe_tick : tick);
  if (keyframe == nullptr) return nullptr;
  if (keyframe->message.tick == tick) return &keyframe->message;
  if (whole_tick_ != tick || whole_keyframe_sequence_ != keyframe->sequence) {
    if (!wire::applyChanges(keyframe->message, *changes, whole_)) return nullptr;
    whole_tick_ = tick;
    whole_keyframe_sequence_ = keyframe->sequence;
  }
  return &whole_;
}

const hypotheses_t* HypothesesInput::latest() const {
  if (const hypothesis_changes_t* newest = changes_.latest())
    if (const hypotheses_t* whole = ofTick(newest->tick)) return whole;
  const auto* keyframe = keyframes_.latest();
  return keyframe == nullptr ? nullptr : &keyframe->message;
}

std::string HypothesesInput::lackingChannel(int64_t tick) const {
  return changes_.empty() || changes_.has(tick) ? channel() : std::string(channels::kHypothesisChanges.name);
}

}  // namespace beft::expert
