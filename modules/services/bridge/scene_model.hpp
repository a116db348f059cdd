// The newest of what the viewer's own topics are made of, kept as received
// bytes and turned into Foxglove messages only when a viewer wants them:
// /scene (ground truth, robot, hypotheses with their changes applied, what
// was heard, the plan), /tf, /obstacle_map (keyframe and changes), and the
// camera's colour and depth images.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lib/wire/obstacle_map_changes.hpp"

namespace beft::bridge {

// The topics made here.
enum class DerivedTopic { kScene, kTransforms, kObstacleMap, kCameraColor, kCameraDepth };
inline constexpr DerivedTopic kDerivedTopics[] = {DerivedTopic::kScene, DerivedTopic::kTransforms,
                                                  DerivedTopic::kObstacleMap, DerivedTopic::kCameraColor,
                                                  DerivedTopic::kCameraDepth};

class SceneModel {
 public:
  // Keeps a message of any channel (plain name) if a topic is made of it;
  // true when it changed what `topic` shows.
  void take(const std::string& channel, const uint8_t* data, std::size_t size);
  bool changed(DerivedTopic topic) const { return changed_[index(topic)]; }
  void clearChanged(DerivedTopic topic) { changed_[index(topic)] = false; }

  // The topic's message from what is kept; nothing when its inputs are
  // missing or refused (`why` then says why, when it is worth saying).
  std::optional<nlohmann::json> build(DerivedTopic topic, std::string* why = nullptr);

 private:
  static std::size_t index(DerivedTopic topic) { return static_cast<std::size_t>(topic); }
  std::optional<nlohmann::json> scene(std::string* why);
  std::optional<nlohmann::json> transforms();
  std::optional<nlohmann::json> obstacleMap(std::string* why);
  std::optional<nlohmann::json> image(const std::vector<uint8_t>& bytes, const char* channel, std::string* why);

  std::vector<uint8_t> objects_, robot_, hypotheses_, hypothesis_changes_, heard_, plan_;
  std::vector<uint8_t> map_, map_changes_, color_, depth_;
  bool changed_[5] = {false, false, false, false, false};
  planners::ObstacleMapAssembler maps_;
};

}  // namespace beft::bridge
