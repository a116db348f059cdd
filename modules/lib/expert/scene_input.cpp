#include "scene_input.hpp"

namespace beft::expert {

SceneInput::SceneInput(Expert& owner, std::size_t capacity)
    : InputPortBase(owner, channels::kGroundTruth.name, channels::kGroundTruth.typeName()),
      scenes_(capacity),
      versions_(owner, channels::kSceneVersion, 16, {}, /*optional_until_heard=*/true) {}

bool SceneInput::receive(const void* data, int size) {
  scene_objects_t message{};
  if (!decodeMessage(channel(), data, size, message)) return false;
  const int64_t utime = message.utime;
  scenes_.store(std::move(message), utime);
  return true;
}

const blackboard::ChannelHistory<scene_objects_t>::Entry* SceneInput::entryOfTick(int64_t tick) const {
  for (const auto* entry = scenes_.latest(); entry != nullptr; entry = scenes_.atOrBefore(entry->utime - 1))
    if (entry->message.tick == tick) return entry;
  return nullptr;
}

const scene_objects_t* SceneInput::ofTick(int64_t tick) const {
  const scene_version_t* version = versions_.ofTick(tick);
  // No version for this tick: a message of the tick itself is in force
  // (the world sends one exactly when it is); otherwise wait for the version.
  const auto* entry = entryOfTick(version != nullptr ? version->scene_tick : tick);
  if (entry == nullptr) return nullptr;
  if (entry->message.tick == tick) return &entry->message;
  if (restamped_from_sequence_ != entry->sequence || restamped_from_tick_ != entry->message.tick) {
    restamped_ = entry->message;
    restamped_from_sequence_ = entry->sequence;
    restamped_from_tick_ = entry->message.tick;
  }
  restamped_.utime = version->utime;
  restamped_.tick = tick;
  return &restamped_;
}

const scene_objects_t* SceneInput::latest() const {
  const auto* newest = scenes_.latest();
  return newest == nullptr ? nullptr : &newest->message;
}

std::string SceneInput::lackingChannel(int64_t tick) const {
  return versions_.has(tick) ? channel() : std::string(channels::kSceneVersion.name);
}

}  // namespace beft::expert
