// Every LCM channel of the blackboard with the message type it carries,
// declared once. A constant such as channels::kVision is the channel's name
// (it converts to const char*) and knows its type, so an expert's port, the
// blackboard's channel table, spy and replay all take both from here.
#pragma once

#include <cstring>
#include <ostream>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <beft/acoustic_percepts_t.hpp>
#include <beft/bb_query_t.hpp>
#include <beft/bb_snapshot_t.hpp>
#include <beft/binaural_block_t.hpp>
#include <beft/camera_frame_t.hpp>
#include <beft/contact_t.hpp>
#include <beft/scene_version_t.hpp>
#include <beft/done_t.hpp>
#include <beft/dynamic_weights_t.hpp>
#include <beft/felt_contacts_t.hpp>
#include <beft/fire_t.hpp>
#include <beft/frontier_t.hpp>
#include <beft/geometry_percepts_t.hpp>
#include <beft/heartbeat_t.hpp>
#include <beft/hypotheses_t.hpp>
#include <beft/hypothesis_changes_t.hpp>
#include <beft/labels_t.hpp>
#include <beft/marking_t.hpp>
#include <beft/obstacle_map_changes_t.hpp>
#include <beft/obstacle_map_t.hpp>
#include <beft/plan_request_t.hpp>
#include <beft/plan_result_t.hpp>
#include <beft/process_rejects_t.hpp>
#include <beft/record_status_t.hpp>
#include <beft/repair_request_t.hpp>
#include <beft/robot_command_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/run_beacon_t.hpp>
#include <beft/run_control_t.hpp>
#include <beft/run_status_t.hpp>
#include <beft/scene_objects_t.hpp>
#include <beft/sender_state_t.hpp>
#include <beft/task_command_t.hpp>
#include <beft/task_events_t.hpp>
#include <beft/task_stack_t.hpp>
#include <beft/visual_percepts_t.hpp>

namespace beft {

// "beft.robot_state_t": the name LCM tools show for a generated type.
template <typename Message>
std::string lcmTypeName() {
  return std::string("beft.") + Message::getTypeName();
}

namespace channels {

// A channel's name and, in its type, the message it carries. It stands for
// its name wherever a std::string is taken (lcm::LCM::publish, subscribe).
template <typename Message>
struct Channel {
  using message_type = Message;
  const char* name;
  operator std::string() const { return name; }
  std::string typeName() const { return lcmTypeName<Message>(); }
};

template <typename Message>
bool operator==(std::string_view channel, Channel<Message> known) { return channel == known.name; }
template <typename Message>
bool operator==(Channel<Message> known, std::string_view channel) { return channel == known.name; }
template <typename Message>
bool operator!=(std::string_view channel, Channel<Message> known) { return channel != known.name; }
template <typename Message>
std::ostream& operator<<(std::ostream& out, Channel<Message> channel) { return out << channel.name; }

// Which plane a channel belongs to (DESIGN.md: the blackboard is the data
// plane, the arbiter the control plane).
enum class Plane {
  kData,     // what the world and the experts publish for a tick: two runs of one scenario and seed
             // publish alike, and runs are compared by these (tests, beft bench faults)
  kReport,   // published by an expert for a tick, for people and tools, not compared (TASK_EVENTS)
  kService,  // requests to and answers of services (PLAN_RESULT holds the wall-clock planning time)
  kControl,  // the arbiter's tokens, the experts' answers and the run's state
  kUrlWide,  // every run on the URL announces itself
  kTransport,  // the transport's own repair traffic: not the run's, never recorded
};

// X(constant, name, type, plane): the one list of the blackboard's channels.
#define BEFT_CHANNELS(X)                                                                              \
  /* Sensor side (world process). */                                                               \
  X(kGroundTruth, "GT_OBJECTS", scene_objects_t, Data) /* when the scene changes, and keyframes */  \
  X(kSceneVersion, "GT_VERSION", scene_version_t, Data) /* every tick: which GT_OBJECTS holds */    \
  X(kRobotState, "ROBOT_STATE", robot_state_t, Data)                                                \
  X(kContact, "CONTACT", contact_t, Data)                                                           \
  X(kCameraColor, "CAMERA_COLOR", camera_frame_t, Data)                                             \
  X(kCameraDepth, "CAMERA_DEPTH", camera_frame_t, Data)                                             \
  X(kCameraInstance, "CAMERA_INSTANCE", camera_frame_t, Data)                                       \
  X(kRobotCommand, "ROBOT_CMD", robot_command_t, Data) /* the tasks expert's */                     \
  X(kEars, "EARS", binaural_block_t, Data) /* beft-ears, with --acoustics binaural */                \
  /* Low-level experts. */                                                                         \
  X(kGeometry, "GEOMETRY", geometry_percepts_t, Data)                                               \
  X(kVision, "VISION", visual_percepts_t, Data)                                                     \
  X(kObstacleMap, "OBSTACLE_MAP", obstacle_map_t, Data) /* at keyframes: the whole map */          \
  X(kObstacleMapChanges, "OBSTACLE_MAP_CHANGES", obstacle_map_changes_t, Data) /* every tick */      \
  X(kObstacleMapFelt, "OBSTACLE_MAP_FELT", felt_contacts_t, Data) /* every tick: contacts marked */  \
  X(kAudio, "AUDIO", acoustic_percepts_t, Data)                                                     \
  /* Mid-level experts. */                                                                         \
  X(kLabelsVisual, "LABELS_VISUAL", labels_t, Data)                                                 \
  X(kLabelsAcoustic, "LABELS_ACOUSTIC", labels_t, Data)                                             \
  /* High-level experts. */                                                                        \
  X(kHypotheses, "HYPOTHESES", hypotheses_t, Data) /* at keyframes: the whole list */              \
  X(kHypothesisChanges, "HYPOTHESIS_CHANGES", hypothesis_changes_t, Data) /* every tick */          \
  X(kDynamicWeights, "DYNAMIC_WEIGHTS", dynamic_weights_t, Data)                                    \
  /* Tasks and planning. */                                                                        \
  X(kTaskStack, "TASK_STACK", task_stack_t, Data)                                                   \
  X(kTaskCommand, "TASK_COMMAND", task_command_t, Data) /* audio, dw, exploration; beft task */     \
  X(kTaskEvents, "TASK_EVENTS", task_events_t, Report)                                              \
  X(kPlanRequest, "PLAN_REQUEST", plan_request_t, Data) /* the tasks expert's */                    \
  X(kPlanResult, "PLAN_RESULT", plan_result_t, Service)                                             \
  /* Control plane (arbiter). */                                                                   \
  X(kFire, "FIRE", fire_t, Control)                                                                 \
  X(kDone, "DONE", done_t, Control)                                                                 \
  X(kHeartbeat, "HEARTBEAT", heartbeat_t, Control)                                                  \
  X(kMarking, "MARKING", marking_t, Control)                                                        \
  X(kRunStatus, "RUN_STATUS", run_status_t, Control)                                                \
  X(kStopRequest, "STOP_REQUEST", run_status_t, Control) /* end the run after this tick */          \
  X(kFrontier, "FRONTIER", frontier_t, Control) /* what FIREs come after (lib/expert/frontier.hpp) */ \
  X(kRunControl, "RUN_CONTROL", run_control_t, Control) /* pause, step, run: from viewers */          \
  X(kRunControlState, "RUN_CONTROL_STATE", run_control_t, Control) /* the arbiter's answer */        \
  /* Blackboard service. */                                                                        \
  X(kBlackboardQuery, "BB_QUERY", bb_query_t, Service)                                              \
  /* The recorder's account of its log. */                                                        \
  X(kRecordStatus, "RECORD_STATUS", record_status_t, Report)                                        \
  /* What each process refused (lib/wire/reject_report.hpp). */                                    \
  X(kProcessRejects, "PROCESS_REJECTS", process_rejects_t, Report)                                  \
  /* Loss repair (lib/transport/reliable_sender.hpp). */                                            \
  X(kRepairRequest, "BEFT_REPAIR", repair_request_t, Transport)                                     \
  X(kSenderState, "BEFT_SENDERS", sender_state_t, Transport)                                        \
  /* URL-wide: every run announces itself (run_identity.hpp). */                                   \
  X(kRunBeacons, "BEFT_RUNS", run_beacon_t, UrlWide)

#define BEFT_DECLARE_CHANNEL(constant, name, type, plane) inline constexpr Channel<type> constant{name};
BEFT_CHANNELS(BEFT_DECLARE_CHANNEL)
#undef BEFT_DECLARE_CHANNEL

// The blackboard answers a query on BB_SNAPSHOT_<requester> (bb_snapshot_t).
inline constexpr Channel<bb_snapshot_t> kBlackboardSnapshotPrefix{"BB_SNAPSHOT_"};

struct ChannelEntry {
  const char* name;
  std::string type;  // e.g. "beft.robot_state_t"
  Plane plane;
};

// Every channel of the list above with its type, in that order.
inline const std::vector<ChannelEntry>& allChannels() {
#define BEFT_CHANNEL_ENTRY(constant, name, type, plane) ChannelEntry{name, lcmTypeName<type>(), Plane::k##plane},
  static const std::vector<ChannelEntry> entries = {BEFT_CHANNELS(BEFT_CHANNEL_ENTRY)};
#undef BEFT_CHANNEL_ENTRY
  return entries;
}

// Whether a channel is of the data plane (Plane::kData in the list above).
inline bool isDataPlaneChannel(const std::string& channel) {
  static const std::set<std::string> names = [] {
    std::set<std::string> data;
    for (const auto& entry : allChannels())
      if (entry.plane == Plane::kData) data.insert(entry.name);
    return data;
  }();
  return names.count(channel) > 0;
}

// The type carried on a channel: "beft.bb_snapshot_t" for any
// "BB_SNAPSHOT_<requester>", "" for a channel not in the list.
inline std::string typeOfChannel(const std::string& channel) {
  for (const auto& entry : allChannels())
    if (channel == entry.name) return entry.type;
  const char* prefix = kBlackboardSnapshotPrefix.name;
  if (channel.compare(0, std::strlen(prefix), prefix) == 0) return kBlackboardSnapshotPrefix.typeName();
  return "";
}

}  // namespace channels
}  // namespace beft
