#include "lib/expert/obstacle_map_input.hpp"

namespace beft::expert {

namespace {
// The same rectangle with the same cells (whatever tick it was sent at).
bool sameChanges(const obstacle_map_changes_t& a, const obstacle_map_changes_t& b) {
  return a.keyframe_tick == b.keyframe_tick && a.x0 == b.x0 && a.y0 == b.y0 && a.width == b.width &&
         a.height == b.height && a.encoding == b.encoding && a.data == b.data;
}
}  // namespace

std::shared_ptr<const planners::ObstacleCells> ObstacleMapInput::ofTick(int64_t tick) const {
  const Parts parts = partsOfTick(tick);
  const obstacle_map_changes_t* changes = parts.per_tick;
  const Entry* keyframe = parts.keyframe;
  if (keyframe == nullptr) return nullptr;
  obstacle_map_changes_t none{};
  none.keyframe_tick = keyframe->message.tick;
  const obstacle_map_changes_t& applied = changes != nullptr ? *changes : none;
  if (made_ && made_from_keyframe_ == keyframe->sequence && sameChanges(made_from_changes_, applied)) return made_;
  made_ = assembler_.mapOf(keyframe->message, &applied);
  made_from_keyframe_ = keyframe->sequence;
  made_from_changes_ = applied;
  if (assembler_.lastChangedCells()) ++version_;
  return made_;
}

std::shared_ptr<const planners::ObstacleCells> ObstacleMapInput::latest() const {
  if (const obstacle_map_changes_t* newest = newestPerTick())
    if (auto map = ofTick(newest->tick)) return map;
  const Entry* keyframe = newestKeyframe();
  return keyframe == nullptr ? nullptr : ofTick(keyframe->message.tick);
}

}  // namespace beft::expert
