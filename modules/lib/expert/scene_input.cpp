#include "lib/expert/scene_input.hpp"

namespace beft::expert {

const scene_objects_t* SceneInput::ofTick(int64_t tick) const {
  const Parts parts = partsOfTick(tick);
  if (parts.keyframe == nullptr) return nullptr;
  const auto& entry = *parts.keyframe;
  if (entry.message.tick == tick) return &entry.message;
  if (restamped_from_sequence_ != entry.sequence || restamped_from_tick_ != entry.message.tick) {
    restamped_ = entry.message;
    restamped_from_sequence_ = entry.sequence;
    restamped_from_tick_ = entry.message.tick;
  }
  restamped_.utime = parts.per_tick->utime;  // a later tick's: named by its version
  restamped_.tick = tick;
  return &restamped_;
}

const scene_objects_t* SceneInput::latest() const {
  const Entry* newest = newestKeyframe();
  return newest == nullptr ? nullptr : &newest->message;
}

}  // namespace beft::expert
