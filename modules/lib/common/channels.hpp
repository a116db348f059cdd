// LCM channel names of the blackboard: one place so no process misspells one.
#pragma once

namespace beft::channels {
// Sensor side (world process).
inline constexpr const char* kGroundTruth = "GT_OBJECTS";          // scene_objects_t
inline constexpr const char* kRobotState = "ROBOT_STATE";          // robot_state_t
inline constexpr const char* kCameraColor = "CAMERA_COLOR";        // camera_frame_t
inline constexpr const char* kCameraDepth = "CAMERA_DEPTH";        // camera_frame_t
inline constexpr const char* kCameraInstance = "CAMERA_INSTANCE";  // camera_frame_t
inline constexpr const char* kRobotCommand = "ROBOT_CMD";          // robot_command_t
// Low-level experts.
inline constexpr const char* kGeometry = "GEOMETRY";               // geometry_percepts_t
inline constexpr const char* kVision = "VISION";                   // visual_percepts_t
inline constexpr const char* kObstacleMap = "OBSTACLE_MAP";        // obstacle_map_t
inline constexpr const char* kAudio = "AUDIO";                     // acoustic_percepts_t
// Mid-level experts.
inline constexpr const char* kLabelsVisual = "LABELS_VISUAL";      // labels_t
inline constexpr const char* kLabelsAcoustic = "LABELS_ACOUSTIC";  // labels_t
// High-level experts.
inline constexpr const char* kHypotheses = "HYPOTHESES";           // hypotheses_t
inline constexpr const char* kDynamicWeights = "DYNAMIC_WEIGHTS";  // dynamic_weights_t
// Tasks and planning.
inline constexpr const char* kTaskStack = "TASK_STACK";            // task_stack_t
inline constexpr const char* kTaskCommand = "TASK_COMMAND";        // task_command_t
inline constexpr const char* kTaskEvents = "TASK_EVENTS";          // task_events_t
inline constexpr const char* kPlanRequest = "PLAN_REQUEST";        // plan_request_t
inline constexpr const char* kPlanResult = "PLAN_RESULT";          // plan_result_t
// Control plane (arbiter).
inline constexpr const char* kFire = "FIRE";                       // fire_t
inline constexpr const char* kDone = "DONE";                       // done_t
inline constexpr const char* kHeartbeat = "HEARTBEAT";             // heartbeat_t
inline constexpr const char* kMarking = "MARKING";                 // marking_t
inline constexpr const char* kRunStatus = "RUN_STATUS";            // run_status_t
inline constexpr const char* kStopRequest = "STOP_REQUEST";        // run_status_t: end the run after this tick
// Blackboard service.
inline constexpr const char* kBlackboardQuery = "BB_QUERY";        // bb_query_t
inline constexpr const char* kBlackboardSnapshotPrefix = "BB_SNAPSHOT_";  // + requester: bb_snapshot_t
}  // namespace beft::channels
