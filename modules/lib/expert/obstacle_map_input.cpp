#include "obstacle_map_input.hpp"

namespace beft::expert {

namespace {
// The same rectangle with the same cells (whatever tick it was sent at).
bool sameChanges(const obstacle_map_changes_t& a, const obstacle_map_changes_t& b) {
  return a.keyframe_tick == b.keyframe_tick && a.x0 == b.x0 && a.y0 == b.y0 && a.width == b.width &&
         a.height == b.height && a.encoding == b.encoding && a.data == b.data;
}
}  // namespace

ObstacleMapInput::ObstacleMapInput(Expert& owner, std::size_t capacity)
    : InputPortBase(owner, channels::kObstacleMap.name, channels::kObstacleMap.typeName()),
      keyframes_(capacity),
      changes_(owner, channels::kObstacleMapChanges, 4, {}, /*optional_until_heard=*/true) {}

bool ObstacleMapInput::receive(const void* data, int size) {
  obstacle_map_t message{};
  if (!decodeMessage(channel(), data, size, message)) return false;
  const int64_t utime = message.utime;
  keyframes_.store(std::move(message), utime);
  return true;
}

const blackboard::ChannelHistory<obstacle_map_t>::Entry* ObstacleMapInput::keyframeOfTick(int64_t tick) const {
  for (const auto* entry = keyframes_.latest(); entry != nullptr; entry = keyframes_.atOrBefore(entry->utime - 1))
    if (entry->message.tick == tick) return entry;
  return nullptr;
}

bool ObstacleMapInput::has(int64_t tick) const {
  const obstacle_map_changes_t* changes = changes_.ofTick(tick);
  return keyframeOfTick(changes != nullptr ? changes->keyframe_tick : tick) != nullptr;
}

std::shared_ptr<const planners::ObstacleCells> ObstacleMapInput::ofTick(int64_t tick) const {
  const obstacle_map_changes_t* changes = changes_.ofTick(tick);
  // No changes for this tick: a whole map of the tick itself holds (a
  // keyframe, or a log from before the changes).
  const auto* keyframe = keyframeOfTick(changes != nullptr ? changes->keyframe_tick : tick);
  if (keyframe == nullptr) return nullptr;
  obstacle_map_changes_t none{};
  none.keyframe_tick = keyframe->message.tick;
  const obstacle_map_changes_t& applied = changes != nullptr ? *changes : none;
  if (made_ && made_from_keyframe_ == keyframe->sequence && sameChanges(made_from_changes_, applied)) return made_;
  made_ = assembler_.mapOf(keyframe->message, &applied);
  made_from_keyframe_ = keyframe->sequence;
  made_from_changes_ = applied;
  ++version_;
  return made_;
}

std::shared_ptr<const planners::ObstacleCells> ObstacleMapInput::latest() const {
  if (const obstacle_map_changes_t* newest = changes_.latest())
    if (auto map = ofTick(newest->tick)) return map;
  const auto* keyframe = keyframes_.latest();
  return keyframe == nullptr ? nullptr : ofTick(keyframe->message.tick);
}

std::string ObstacleMapInput::lackingChannel(int64_t tick) const {
  return changes_.empty() || changes_.has(tick) ? channel() : std::string(channels::kObstacleMapChanges.name);
}

}  // namespace beft::expert
