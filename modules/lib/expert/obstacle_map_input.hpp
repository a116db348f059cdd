// The obstacle map as an expert reads it. The vision expert publishes the
// whole map (OBSTACLE_MAP) only at keyframes and, every tick, the rectangle
// changed since (OBSTACLE_MAP_CHANGES); this port keeps both and gives the
// decoded map of a tick, the keyframe decoded once:
//
//   expert::ObstacleMapInput map_{*this};
//   if (auto cells = map_.latest()) use(*cells, map_.version());
//
// Logs from before OBSTACLE_MAP_CHANGES carry the whole map at every tick:
// while no changes have been heard, the map of tick k is the message of tick k.
#pragma once

#include <cstdint>
#include <memory>

#include "lib/expert/keyframed_input.hpp"
#include "lib/wire/obstacle_map_changes.hpp"

namespace beft::expert {

class ObstacleMapInput
    : public KeyframedInput<obstacle_map_t, obstacle_map_changes_t, &obstacle_map_changes_t::keyframe_tick> {
 public:
  explicit ObstacleMapInput(Expert& owner, std::size_t capacity = 2)
      : KeyframedInput(owner, channels::kObstacleMap, channels::kObstacleMapChanges, capacity) {}

  // The map of tick k, or null if what makes it has not arrived. Throws
  // planners::ObstacleMapError if the messages do not make a map.
  std::shared_ptr<const planners::ObstacleCells> ofTick(int64_t tick) const;
  // The map of the newest tick that can be made, or null; throws as ofTick.
  std::shared_ptr<const planners::ObstacleCells> latest() const;
  // Grows whenever the map last returned has other cells than the one before
  // (a new keyframe of the same cells keeps it).
  uint64_t version() const { return version_; }
  bool has(int64_t tick) const { return partsOfTick(tick).keyframe != nullptr; }

  bool lacksTick(int64_t tick) const override { return !empty() && !has(tick); }

 private:
  mutable planners::ObstacleMapAssembler assembler_;
  // The map last made, and what it was made of.
  mutable std::shared_ptr<const planners::ObstacleCells> made_;
  mutable uint64_t made_from_keyframe_ = 0;  // entry sequence
  mutable obstacle_map_changes_t made_from_changes_{};
  mutable uint64_t version_ = 0;
};

}  // namespace beft::expert
