#include "blackboard/channel_types.hpp"

#include <map>

#include "channels.hpp"

namespace beft::blackboard {

std::string expectedTypeOfChannel(const std::string& channel) {
  namespace ch = beft::channels;
  static const std::map<std::string, std::string> types = {
      {ch::kGroundTruth, "beft.scene_objects_t"},
      {ch::kRobotState, "beft.robot_state_t"},
      {ch::kCameraColor, "beft.camera_frame_t"},
      {ch::kCameraDepth, "beft.camera_frame_t"},
      {ch::kCameraInstance, "beft.camera_frame_t"},
      {ch::kRobotCommand, "beft.robot_command_t"},
      {ch::kGeometry, "beft.geometry_percepts_t"},
      {ch::kVision, "beft.visual_percepts_t"},
      {ch::kObstacleMap, "beft.obstacle_map_t"},
      {ch::kAudio, "beft.acoustic_percepts_t"},
      {ch::kLabelsVisual, "beft.labels_t"},
      {ch::kLabelsAcoustic, "beft.labels_t"},
      {ch::kHypotheses, "beft.hypotheses_t"},
      {ch::kDynamicWeights, "beft.dynamic_weights_t"},
      {ch::kTaskStack, "beft.task_stack_t"},
      {ch::kTaskCommand, "beft.task_command_t"},
      {ch::kPlanRequest, "beft.plan_request_t"},
      {ch::kPlanResult, "beft.plan_result_t"},
      {ch::kFire, "beft.fire_t"},
      {ch::kDone, "beft.done_t"},
      {ch::kHeartbeat, "beft.heartbeat_t"},
      {ch::kMarking, "beft.marking_t"},
      {ch::kRunStatus, "beft.run_status_t"},
      {ch::kStopRequest, "beft.run_status_t"},
      {ch::kBlackboardQuery, "beft.bb_query_t"},
  };
  if (auto it = types.find(channel); it != types.end()) return it->second;
  const std::string snapshot_prefix = ch::kBlackboardSnapshotPrefix;
  if (channel.compare(0, snapshot_prefix.size(), snapshot_prefix) == 0) return "beft.bb_snapshot_t";
  return "";
}

}  // namespace beft::blackboard
