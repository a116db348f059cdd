// What the three "whole at keyframes, small message every tick" inputs share
// (SceneInput, HypothesesInput, ObstacleMapInput): a big message (Whole) sent
// only when it changed or at a keyframe, and a small one every tick (PerTick)
// naming, in its field kKeyframeTick, the Whole message it builds on. The
// port keeps both and finds, for a tick, its PerTick message and that Whole
// message; each port makes the tick's value of them in its own way.
//
// Logs from before the PerTick messages carry a Whole message at every tick:
// while no PerTick message has been heard, tick k's is the Whole of tick k.
#pragma once

#include <cstdint>
#include <string>

#include "lib/expert/ports.hpp"

namespace beft::expert {

template <typename Whole, typename PerTick, int64_t PerTick::*kKeyframeTick>
class KeyframedInput : public InputPortBase {
 public:
  using Entry = typename blackboard::ChannelHistory<Whole>::Entry;

  bool receive(const void* data, int size) override {  // a Whole message
    Whole message{};
    if (!decodeMessage(channel(), data, size, message)) return false;
    const int64_t utime = message.utime;
    keyframes_.store(std::move(message), utime);
    return true;
  }
  bool empty() const { return keyframes_.empty() && per_tick_.empty(); }

  // The PerTick channel while the tick's PerTick message is missing, then
  // the Whole channel (a log from before PerTick messages: the Whole one).
  std::string lackingChannel(int64_t tick) const override {
    const bool log_from_before = per_tick_.empty() && !keyframes_.empty();
    return log_from_before || per_tick_.has(tick - ticks_before_) ? std::string(channel())
                                                                   : std::string(per_tick_.channel());
  }
  // A firing of tick k reads the value of tick k - 1 (lacksTick and
  // lackingChannel ask for that one): for an expert that fires before the
  // one that publishes this input in each tick.
  void readTheTickBefore() {
    ticks_before_ = 1;
    per_tick_.readTheTickBefore();
  }
  void setRead(bool read) override {  // both channels
    InputPortBase::setRead(read);
    per_tick_.setRead(read);
  }

 protected:
  KeyframedInput(Expert& owner, channels::Channel<Whole> whole, channels::Channel<PerTick> per_tick,
                 std::size_t capacity)
      : InputPortBase(owner, whole.name, whole.typeName()),
        keyframes_(capacity),
        per_tick_(owner, per_tick, 16, {}, /*optional_until_heard=*/true) {}

  // What tick k is made of: its PerTick message (null if none) and the Whole
  // message that one names, or without one the Whole message of tick k
  // itself (null if it has not arrived).
  struct Parts {
    const PerTick* per_tick = nullptr;
    const Entry* keyframe = nullptr;
  };
  Parts partsOfTick(int64_t tick) const {
    Parts parts;
    parts.per_tick = per_tick_.ofTick(tick);
    parts.keyframe = keyframeOfTick(parts.per_tick != nullptr ? parts.per_tick->*kKeyframeTick : tick);
    return parts;
  }
  const Entry* newestKeyframe() const { return keyframes_.latest(); }
  int64_t ticksBefore() const { return ticks_before_; }
  const PerTick* newestPerTick() const { return per_tick_.latest(); }

 private:
  const Entry* keyframeOfTick(int64_t tick) const {
    for (const auto* entry = keyframes_.latest(); entry != nullptr; entry = keyframes_.atOrBefore(entry->utime - 1))
      if (entry->message.tick == tick) return entry;
    return nullptr;
  }

  blackboard::ChannelHistory<Whole> keyframes_;
  // Never lacking on its own: the port says what is missing (lackingChannel).
  TickInput<PerTick> per_tick_;
  int64_t ticks_before_ = 0;
};

}  // namespace beft::expert
