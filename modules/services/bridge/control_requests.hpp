// What a viewer may ask of the run, published by the client on one of the
// bridge's control topics (clientPublish, encoding "json"): read from
// untrusted bytes into a request, or into what was wrong with them.
//   /beft/run_control  {"action":"pause"|"run"|"step"}
//   /beft/task         {"action":"goto","x":X,"y":Y[,"yaw":DEG]} | {"action":"look_at","object_id":"ID"}
//                      | {"action":"clear"}                      (x, y in m; yaw in degrees, omitted: any heading)
//   /beft/playback     {"action":"play"[,"speed":S]} | {"action":"pause"} | {"action":"step"}
//                      | {"action":"seek","time_ns":T}            (log mode only)
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace beft::bridge {

inline constexpr const char* kRunControlTopic = "/beft/run_control";
inline constexpr const char* kTaskTopic = "/beft/task";
inline constexpr const char* kPlaybackTopic = "/beft/playback";

bool isControlTopic(std::string_view topic);

struct RunControlRequest {
  enum class Action { kRun, kPause, kStep } action = Action::kRun;
};

struct TaskRequest {
  enum class Action { kGoto, kLookAt, kClear } action = Action::kGoto;
  double x = 0, y = 0;
  std::optional<double> yaw_deg;
  std::string object_id;
};

struct PlaybackRequest {
  enum class Action { kPlay, kPause, kStep, kSeek } action = Action::kPlay;
  std::optional<int64_t> time_ns;
  std::optional<double> speed;
};

struct ControlRequest {
  std::variant<std::monostate, RunControlRequest, TaskRequest, PlaybackRequest> request;
  std::string error;  // what was wrong, when request holds nothing
};

// Never throws: bad JSON, a missing or wrong field, an unknown action or
// topic all come back as an error that names it.
ControlRequest parseControlRequest(std::string_view topic, std::string_view payload);

}  // namespace beft::bridge
