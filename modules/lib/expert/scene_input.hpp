// The ground truth as an expert reads it. The world publishes GT_OBJECTS only
// at ticks where the scene changed and at keyframes, and GT_VERSION at every
// tick naming the GT_OBJECTS message in force (scene_version_t); this port
// keeps both and answers, like a TickInput, with the ground truth of a tick:
//
//   expert::SceneInput scene_{*this};
//   const scene_objects_t* scene = scene_.ofTick(firing.tick);
//
// Logs from before GT_VERSION carry GT_OBJECTS at every tick: while no
// version has been heard, the ground truth of tick k is the message of tick k.
#pragma once

#include <cstdint>
#include <string>

#include "ports.hpp"

namespace beft::expert {

class SceneInput : public InputPortBase {
 public:
  explicit SceneInput(Expert& owner, std::size_t capacity = 4);

  bool receive(const void* data, int size) override;  // a GT_OBJECTS message

  // The ground truth in force at tick k, or null if it has not arrived. Its
  // utime and tick are tick k's (the objects keep the time they were last
  // published at), as if it had been sent at every tick; the pointer holds
  // until the next call.
  const scene_objects_t* ofTick(int64_t tick) const;
  bool has(int64_t tick) const { return ofTick(tick) != nullptr; }
  // The newest GT_OBJECTS message kept, or null.
  const scene_objects_t* latest() const;
  bool empty() const { return scenes_.empty(); }

  bool lacksTick(int64_t tick) const override { return !has(tick); }
  // GT_VERSION while the version of the tick is unknown, else GT_OBJECTS.
  std::string lackingChannel(int64_t tick) const override;

 private:
  const blackboard::ChannelHistory<scene_objects_t>::Entry* entryOfTick(int64_t tick) const;

  blackboard::ChannelHistory<scene_objects_t> scenes_;
  // The message in force restamped for a later tick: copied once per
  // message, restamped per tick.
  mutable scene_objects_t restamped_{};
  mutable int64_t restamped_from_tick_ = -1;
  mutable uint64_t restamped_from_sequence_ = 0;
  // Never lacking on its own: this port says when a version is missing.
  TickInput<scene_version_t> versions_;
};

}  // namespace beft::expert
