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

#include "lib/expert/keyframed_input.hpp"

namespace beft::expert {

class SceneInput : public KeyframedInput<scene_objects_t, scene_version_t, &scene_version_t::scene_tick> {
 public:
  explicit SceneInput(Expert& owner, std::size_t capacity = 4)
      : KeyframedInput(owner, channels::kGroundTruth, channels::kSceneVersion, capacity) {}

  // The ground truth in force at tick k, or null if it has not arrived. Its
  // utime and tick are tick k's (the objects keep the time they were last
  // published at), as if it had been sent at every tick; the pointer holds
  // until the next call.
  const scene_objects_t* ofTick(int64_t tick) const;
  bool has(int64_t tick) const { return ofTick(tick) != nullptr; }
  // The newest GT_OBJECTS message kept, or null.
  const scene_objects_t* latest() const;

  // The ground truth is needed from the first tick on.
  bool lacksTick(int64_t tick) const override { return !has(tick); }

 private:
  // The message in force restamped for a later tick: copied once per
  // message, restamped per tick.
  mutable scene_objects_t restamped_{};
  mutable int64_t restamped_from_tick_ = -1;
  mutable uint64_t restamped_from_sequence_ = 0;
};

}  // namespace beft::expert
