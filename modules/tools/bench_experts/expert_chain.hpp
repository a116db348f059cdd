// The expert hierarchy in one process, without LCM: the six experts wired by
// their channels, fired in the default schedule (low level, then mid level,
// then fusion). The same Expert classes as the live processes, so the chain
// measures and tests exactly what runs live. Used by beft-bench-experts and by
// the scenario tests.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <beft/camera_frame_t.hpp>
#include <beft/hypotheses_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/scene_objects_t.hpp>

#include "lib/expert/expert.hpp"
#include "lib/wire/obstacle_map_changes.hpp"

namespace beft::bench {

class ExpertChain {
 public:
  // parameters: --param values per expert name (e.g. {"fusion", {{"seen_threshold", "0.6"}}}).
  explicit ExpertChain(const std::map<std::string, std::map<std::string, std::string>>& parameters = {});
  ~ExpertChain();

  // Delivers the world's messages of one tick and fires every expert once, in
  // order. Returns the failures ("expert: message"), empty when all went well.
  std::vector<std::string> runTick(const scene_objects_t& scene, const robot_state_t& robot,
                                   const camera_frame_t& depth, const camera_frame_t& instance);

  // The latest message published on a channel, decoded; false if none.
  template <typename Message>
  bool latest(const std::string& channel, Message& message) const {
    const auto it = latest_.find(channel);
    return it != latest_.end() && expert::decodeMessage(channel, it->second.data(), static_cast<int>(it->second.size()), message);
  }
  // The whole list of hypotheses of the latest tick: the latest HYPOTHESES
  // keyframe with the latest HYPOTHESIS_CHANGES applied; false if none.
  bool latestHypotheses(hypotheses_t& whole) const;
  // The obstacle map of the latest tick: the latest OBSTACLE_MAP keyframe
  // with the latest OBSTACLE_MAP_CHANGES written over it; null if none.
  std::shared_ptr<const planners::ObstacleCells> latestObstacleMap() const;
  // Size of the latest message on a channel [bytes], 0 if none.
  std::size_t latestSize(const std::string& channel) const;

  // CPU time spent in each expert's fire() so far, per firing [s] (CPU, not
  // wall time: other processes on a busy machine do not inflate it).
  const std::map<std::string, std::vector<double>>& fireSeconds() const { return fire_seconds_; }
  const std::vector<std::string>& expertNames() const { return names_; }

 private:
  class Bus;
  void deliver(const std::string& channel, const std::vector<uint8_t>& bytes);
  template <typename Message>
  void deliver(const std::string& channel, const Message& message);

  std::vector<std::unique_ptr<expert::Expert>> experts_;
  std::vector<std::string> names_;
  std::vector<std::vector<int>> levels_;  // indices into experts_, fired level by level
  std::map<std::string, std::vector<uint8_t>> latest_;
  std::map<std::string, std::vector<double>> fire_seconds_;
  int64_t next_firing_id_ = 1;
};

// CPU time of the calling thread [s].
double threadCpuSeconds();

}  // namespace beft::bench
