#include "services/bridge/control_requests.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace beft::bridge {

namespace {

using nlohmann::json;

std::string actionOf(const json& body) {
  const auto found = body.find("action");
  if (found == body.end() || !found->is_string()) throw std::invalid_argument("needs \"action\" as a string");
  return found->get<std::string>();
}

double finiteNumber(const json& body, const char* name, double low, double high) {
  const auto found = body.find(name);
  if (found == body.end() || !found->is_number())
    throw std::invalid_argument(std::string("needs \"") + name + "\" as a number");
  const double value = found->get<double>();
  if (!std::isfinite(value) || value < low || value > high)
    throw std::invalid_argument(std::string("\"") + name + "\" out of range [" + std::to_string(low) + ", " +
                                std::to_string(high) + "]");
  return value;
}

RunControlRequest runControl(const json& body) {
  const std::string action = actionOf(body);
  RunControlRequest request;
  if (action == "run") request.action = RunControlRequest::Action::kRun;
  else if (action == "pause") request.action = RunControlRequest::Action::kPause;
  else if (action == "step") request.action = RunControlRequest::Action::kStep;
  else throw std::invalid_argument("unknown action \"" + action + "\" (run, pause, step)");
  return request;
}

TaskRequest task(const json& body) {
  const std::string action = actionOf(body);
  TaskRequest request;
  constexpr double kFar = 1e6;  // [m], [deg]: beyond any scenario, and no overflow downstream
  if (action == "goto") {
    request.action = TaskRequest::Action::kGoto;
    request.x = finiteNumber(body, "x", -kFar, kFar);
    request.y = finiteNumber(body, "y", -kFar, kFar);
    if (body.contains("yaw") && !body["yaw"].is_null()) request.yaw_deg = finiteNumber(body, "yaw", -kFar, kFar);
  } else if (action == "look_at") {
    request.action = TaskRequest::Action::kLookAt;
    const auto found = body.find("object_id");
    if (found == body.end() || !found->is_string() || found->get<std::string>().empty())
      throw std::invalid_argument("look_at needs \"object_id\" as a non-empty string");
    request.object_id = found->get<std::string>();
    if (request.object_id.size() > 256) throw std::invalid_argument("\"object_id\" longer than 256 characters");
  } else if (action == "clear") {
    request.action = TaskRequest::Action::kClear;
  } else {
    throw std::invalid_argument("unknown action \"" + action + "\" (goto, look_at, clear)");
  }
  return request;
}

PlaybackRequest playback(const json& body) {
  const std::string action = actionOf(body);
  PlaybackRequest request;
  if (action == "play") request.action = PlaybackRequest::Action::kPlay;
  else if (action == "pause") request.action = PlaybackRequest::Action::kPause;
  else if (action == "step") request.action = PlaybackRequest::Action::kStep;
  else if (action == "seek") request.action = PlaybackRequest::Action::kSeek;
  else throw std::invalid_argument("unknown action \"" + action + "\" (play, pause, step, seek)");
  if (body.contains("speed") && !body["speed"].is_null()) request.speed = finiteNumber(body, "speed", 0.01, 1000);
  if (request.action == PlaybackRequest::Action::kSeek || body.contains("time_ns")) {
    const double t = finiteNumber(body, "time_ns", 0, 9.2e18);
    request.time_ns = static_cast<int64_t>(t);
  }
  return request;
}

}  // namespace

bool isControlTopic(std::string_view topic) {
  return topic == kRunControlTopic || topic == kTaskTopic || topic == kPlaybackTopic;
}

ControlRequest parseControlRequest(std::string_view topic, std::string_view payload) {
  ControlRequest result;
  const json body = json::parse(payload.begin(), payload.end(), nullptr, false);
  if (body.is_discarded() || !body.is_object()) {
    result.error = std::string(topic) + ": not a JSON object";
    return result;
  }
  try {
    if (topic == kRunControlTopic) result.request = runControl(body);
    else if (topic == kTaskTopic) result.request = task(body);
    else if (topic == kPlaybackTopic) result.request = playback(body);
    else result.error = std::string(topic) + ": not a control topic of this bridge";
  } catch (const std::exception& e) {  // invalid_argument above, or json's own type errors
    result.error = std::string(topic) + ": " + e.what();
  }
  return result;
}

}  // namespace beft::bridge
