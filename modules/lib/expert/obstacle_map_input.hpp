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
#include <string>

#include "obstacle_map_changes.hpp"
#include "ports.hpp"

namespace beft::expert {

class ObstacleMapInput : public InputPortBase {
 public:
  explicit ObstacleMapInput(Expert& owner, std::size_t capacity = 2);

  bool receive(const void* data, int size) override;  // an OBSTACLE_MAP message

  // The map of tick k, or null if what makes it has not arrived. Throws
  // planners::ObstacleMapError if the messages do not make a map.
  std::shared_ptr<const planners::ObstacleCells> ofTick(int64_t tick) const;
  // The map of the newest tick that can be made, or null; throws as ofTick.
  std::shared_ptr<const planners::ObstacleCells> latest() const;
  // Grows whenever the map last returned differs from the one before.
  uint64_t version() const { return version_; }
  bool has(int64_t tick) const;
  bool empty() const { return keyframes_.empty() && changes_.empty(); }

  bool lacksTick(int64_t tick) const override { return !empty() && !has(tick); }
  // OBSTACLE_MAP_CHANGES while the changes of the tick are missing, else OBSTACLE_MAP.
  std::string lackingChannel(int64_t tick) const override;

 private:
  const blackboard::ChannelHistory<obstacle_map_t>::Entry* keyframeOfTick(int64_t tick) const;

  blackboard::ChannelHistory<obstacle_map_t> keyframes_;
  mutable planners::ObstacleMapAssembler assembler_;
  // The map last made, and what it was made of.
  mutable std::shared_ptr<const planners::ObstacleCells> made_;
  mutable uint64_t made_from_keyframe_ = 0;  // entry sequence
  mutable obstacle_map_changes_t made_from_changes_{};
  mutable uint64_t version_ = 0;
  // Never lacking on its own: this port says when changes are missing.
  TickInput<obstacle_map_changes_t> changes_;
};

}  // namespace beft::expert
