#include "services/bridge/scene_model.hpp"

#include <stdexcept>

#include "lib/common/channels.hpp"
#include "lib/foxglove/scene_messages.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/wire/hypothesis_changes.hpp"
#include "lib/wire/obstacle_map_codec.hpp"

namespace beft::bridge {

namespace {

template <typename Message>
bool decodeKept(const char* channel, const std::vector<uint8_t>& bytes, Message& message) {
  return !bytes.empty() && wire::decodeFrom(channel, bytes.data(), bytes.size(), message);
}

}  // namespace

void SceneModel::take(const std::string& channel, const uint8_t* data, std::size_t size) {
  const auto keep = [&](std::vector<uint8_t>& into, std::initializer_list<DerivedTopic> topics) {
    into.assign(data, data + size);
    for (const DerivedTopic topic : topics) changed_[index(topic)] = true;
  };
  namespace c = channels;
  if (channel == c::kGroundTruth) keep(objects_, {DerivedTopic::kScene});
  else if (channel == c::kRobotState) keep(robot_, {DerivedTopic::kScene, DerivedTopic::kTransforms});
  else if (channel == c::kHypotheses) {
    keep(hypotheses_, {DerivedTopic::kScene});
    hypothesis_changes_.clear();  // those of the keyframe before
  } else if (channel == c::kHypothesisChanges) keep(hypothesis_changes_, {DerivedTopic::kScene});
  else if (channel == c::kAudio) keep(heard_, {DerivedTopic::kScene});
  else if (channel == c::kPlanResult) keep(plan_, {DerivedTopic::kScene});
  else if (channel == c::kObstacleMap) {
    keep(map_, {DerivedTopic::kObstacleMap});
    map_changes_.clear();
  } else if (channel == c::kObstacleMapChanges) keep(map_changes_, {DerivedTopic::kObstacleMap});
  else if (channel == c::kCameraColor) keep(color_, {DerivedTopic::kCameraColor});
  else if (channel == c::kCameraDepth) keep(depth_, {DerivedTopic::kCameraDepth});
}

std::optional<nlohmann::json> SceneModel::build(DerivedTopic topic, std::string* why) {
  try {
    switch (topic) {
      case DerivedTopic::kScene: return scene(why);
      case DerivedTopic::kTransforms: return transforms();
      case DerivedTopic::kObstacleMap: return obstacleMap(why);
      case DerivedTopic::kCameraColor: return image(color_, channels::kCameraColor.name, why);
      case DerivedTopic::kCameraDepth: return image(depth_, channels::kCameraDepth.name, why);
    }
  } catch (const std::exception& e) {  // a malformed map or frame: said, never fatal
    if (why) *why = e.what();
  }
  return std::nullopt;
}

std::optional<nlohmann::json> SceneModel::scene(std::string* why) {
  beft::scene_objects_t objects{};
  beft::robot_state_t robot{};
  beft::hypotheses_t keyframe{}, whole{};
  beft::hypothesis_changes_t changes{};
  beft::acoustic_percepts_t heard{};
  beft::plan_result_t plan{};
  foxglove::SceneState state;
  if (decodeKept(channels::kGroundTruth.name, objects_, objects)) state.objects = &objects;
  if (decodeKept(channels::kRobotState.name, robot_, robot)) state.robot = &robot;
  if (decodeKept(channels::kHypotheses.name, hypotheses_, keyframe)) {
    state.hypotheses = &keyframe;
    if (decodeKept(channels::kHypothesisChanges.name, hypothesis_changes_, changes) &&
        wire::applyChanges(keyframe, changes, whole))
      state.hypotheses = &whole;
  }
  if (decodeKept(channels::kAudio.name, heard_, heard)) state.heard = &heard;
  if (decodeKept(channels::kPlanResult.name, plan_, plan)) state.plan = &plan;
  if (!state.objects && !state.robot && !state.hypotheses) {
    if (why) *why = "no scene heard yet";
    return std::nullopt;
  }
  return foxglove::sceneUpdate(state);
}

std::optional<nlohmann::json> SceneModel::transforms() {
  beft::robot_state_t robot{};
  if (!decodeKept(channels::kRobotState.name, robot_, robot)) return std::nullopt;
  return foxglove::frameTransforms(robot);
}

std::optional<nlohmann::json> SceneModel::obstacleMap(std::string* why) {
  beft::obstacle_map_t keyframe{};
  if (!decodeKept(channels::kObstacleMap.name, map_, keyframe)) {
    if (why) *why = "no obstacle map keyframe heard yet";
    return std::nullopt;
  }
  beft::obstacle_map_changes_t changes{};
  const bool with_changes = decodeKept(channels::kObstacleMapChanges.name, map_changes_, changes) &&
                            changes.keyframe_tick == keyframe.tick;
  const auto cells = maps_.mapOf(keyframe, with_changes ? &changes : nullptr);
  const int64_t utime = with_changes ? changes.utime : keyframe.utime;
  const int64_t tick = with_changes ? changes.tick : keyframe.tick;
  return foxglove::occupancyGrid(planners::makeObstacleMap(*cells, beft::obstacle_map_t::ENCODING_RAW, utime, tick));
}

std::optional<nlohmann::json> SceneModel::image(const std::vector<uint8_t>& bytes, const char* channel,
                                                std::string* why) {
  beft::camera_frame_t frame{};
  if (!decodeKept(channel, bytes, frame)) {
    if (why && !bytes.empty()) *why = std::string("a ") + channel + " frame that does not decode";
    return std::nullopt;
  }
  return foxglove::cameraImage(frame);
}

}  // namespace beft::bridge
