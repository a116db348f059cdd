// beft-planner: the planner service. Subscribes OBSTACLE_MAP and
// PLAN_REQUEST, answers each request once on PLAN_RESULT, and sends a
// HEARTBEAT every second, and at once to an arbiter that waits for it.
#include "channels.hpp"
#include "heap_retention.hpp"
#include "lcm_url.hpp"
#include "log.hpp"
#include "ompl_planner.hpp"
#include "planner_factory.hpp"
#include "planner_service.hpp"
#include "control_messages.hpp"
#include "transport.hpp"

#include <beft/heartbeat_t.hpp>
#include <beft/run_status_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include <CLI/CLI.hpp>

#include <atomic>
#include <chrono>
#include <csignal>
#include <deque>
#include <unistd.h>

namespace {

std::atomic<bool> g_stop{false};

void onSignal(int) { g_stop = true; }

int64_t wallMicros() {
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

std::string hostName() {
  char name[256] = {0};
  if (gethostname(name, sizeof name - 1) != 0) return "unknown";
  return name;
}

// LCM handlers only store; planning happens in the main loop.
// Keeps the newest map (bytes only: decoded when a request needs it) and the
// requests in arrival order.
class Inbox {
 public:
  void onMessage(const beft::transport::Message& message) {
    const int size = static_cast<int>(message.size);
    if (message.channel == beft::channels::kObstacleMap) {
      latest_map.assign(message.data, message.data + message.size);
      has_map = true;
    } else if (message.channel == beft::channels::kPlanRequest) {
      beft::plan_request_t request;
      if (request.decode(message.data, 0, size) == size) requests.push_back(std::move(request));
      else beft::log::warn("dropped a ", size, "-byte PLAN_REQUEST that does not decode");
    } else if (message.channel == beft::channels::kRunStatus) {
      beft::run_status_t status;
      if (status.decode(message.data, 0, size) == size && status.state == beft::run_status_t::STATE_WAITING)
        arbiter_waiting = true;
    }
  }
  std::vector<uint8_t> latest_map;
  bool has_map = false;
  bool arbiter_waiting = false;  // an arbiter waits for heartbeats: answer without waiting for the period
  std::deque<beft::plan_request_t> requests;
};

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  beft::retainFreedHeapMemory();
  namespace bp = beft::planners;
  CLI::App app{
      "The planner service: plans on the robot's current obstacle map (OBSTACLE_MAP: what the camera has "
      "seen so far; unknown cells count as free) and answers each PLAN_REQUEST (start, goal, planner, time "
      "budget; world metres) once on PLAN_RESULT with sparse waypoints, each with its heading of travel and "
      "the goal heading at the end. Obstacles are inflated by the robot radius."};
  beft::planner_service::ServiceConfig config;
  std::string lcm_url = beft::defaultLcmUrl();
  std::string process_name = "planner";
  std::vector<std::string> params;
  app.add_option("--planner", config.default_planner,
                 "planner for requests that name none: " + joined(bp::plannerNames()))
      ->capture_default_str();
  app.add_option("--robot-radius", config.robot_radius, "obstacle inflation [m]")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--default-budget", config.default_budget, "time budget of requests without one [s]")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--goal-snap", config.goal_snap, "how far a blocked goal may move to a free cell [m]")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--seed", config.seed, "seed of randomised planners (plus the request id)")->capture_default_str();
  app.add_option("--param", params, "potential-field parameter name=value, repeatable: " +
                                        joined(bp::PotentialFieldParams::names()));
  app.add_option("--lcm-url", lcm_url, "LCM URL")->capture_default_str();
  app.add_option("--name", process_name, "process name in logs and heartbeats")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  beft::log::setProcessName(process_name);
  std::unique_ptr<beft::planner_service::PlannerService> service;
  try {
    for (const auto& p : params) config.pf_params.push_back(bp::splitParameter(p));
    bp::seedOmpl(config.seed);
    service = std::make_unique<beft::planner_service::PlannerService>(config);
  } catch (const std::exception& e) {
    beft::log::error(e.what());
    return 2;
  }

  lcm::LCM lcm(lcm_url);
  if (!lcm.good()) {
    beft::log::error("cannot open LCM at ", lcm_url);
    return 1;
  }
  // On udpm the maps (one a tick) queue on a socket nothing waits on and are
  // read when a request comes; requests wake the process.
  Inbox inbox;
  const beft::transport::Handler to_inbox = [&inbox](const beft::transport::Message& m) { inbox.onMessage(m); };
  beft::transport::Selection maps, requests;
  maps.rules = {beft::transport::channelRule(beft::channels::kObstacleMap)};
  requests.rules = {beft::transport::channelRule(beft::channels::kPlanRequest)};
  requests.rules.push_back(
      beft::control::runStatusIn(beft::run_status_t::STATE_WAITING, "an arbiter waiting for heartbeats"));
  std::unique_ptr<beft::transport::Receiver> request_source, map_source;
  try {
    beft::transport::SplitReceivers sources = beft::transport::openSplitReceivers(lcm, lcm_url, requests, maps, 16, 1000);
    request_source = std::move(sources.wake);
    map_source = std::move(sources.queued);
  } catch (const std::exception& e) {
    beft::log::error("cannot receive on ", lcm_url, ": ", e.what());
    return 1;
  }
  if (map_source) beft::log::info("maps: ", map_source->description());
  beft::log::info("requests: ", request_source->description());
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
  beft::log::info("planning with ", config.default_planner, " (robot radius ", config.robot_radius, " m) on ",
                  lcm_url);

  beft::heartbeat_t heartbeat;
  heartbeat.process = process_name;
  heartbeat.pid = static_cast<int32_t>(getpid());
  heartbeat.host = hostName();
  heartbeat.last_firing_id = -1;
  auto next_heartbeat = std::chrono::steady_clock::now();
  auto last_waiting_answer = next_heartbeat - std::chrono::seconds(1);
  int64_t answered = 0;
  while (!g_stop) {
    const auto now = std::chrono::steady_clock::now();
    // An arbiter that started after the last heartbeat waits for the next:
    // answer at once (at most every 50 ms), as the experts do.
    const bool answer_waiting =
        inbox.arbiter_waiting && now - last_waiting_answer > std::chrono::milliseconds(50);
    inbox.arbiter_waiting = false;
    if (now >= next_heartbeat || answer_waiting) {
      heartbeat.utime = wallMicros();
      heartbeat.state = "idle";
      lcm.publish(beft::channels::kHeartbeat, &heartbeat);
      if (answer_waiting) last_waiting_answer = now;
      if (now >= next_heartbeat) next_heartbeat += std::chrono::seconds(1);
    }
    beft::transport::waitReadable({request_source->fd()}, 100);
    // The maps first: a request sees the map sent before it.
    if ((map_source && map_source->drain(to_inbox) < 0) || request_source->drain(to_inbox) < 0) {
      if (g_stop) break;  // interrupted by the stop signal
      beft::log::error("LCM receive failed");
      return 1;
    }
    // Decoded only when a request needs it: the map arrives every tick, requests rarely.
    if (inbox.has_map && !inbox.requests.empty()) {
      try {
        beft::obstacle_map_t map;
        const int size = static_cast<int>(inbox.latest_map.size());
        if (map.decode(inbox.latest_map.data(), 0, size) != size) throw std::invalid_argument("not an obstacle_map_t");
        service->setObstacleMap(map);
      } catch (const std::exception& e) {
        beft::log::warn("ignoring a malformed obstacle map: ", e.what());
      }
      inbox.has_map = false;
    }
    while (!inbox.requests.empty()) {
      const beft::plan_request_t request = inbox.requests.front();
      inbox.requests.pop_front();
      try {
        const auto result = service->handle(request, wallMicros());
        if (!result) {
          beft::log::debug("request ", request.request_id, " was answered before; ignored");
          continue;
        }
        lcm.publish(beft::channels::kPlanResult, &*result);
        ++answered;
        if (result->success) {
          beft::log::info("request ", request.request_id, " (", result->planner, "): ", result->num_waypoints,
                          " waypoints, ", result->length, " m, ", 1000 * result->planning_time, " ms",
                          result->message.empty() ? "" : " - " + result->message);
        } else {
          beft::log::warn("request ", request.request_id, " (", result->planner, ") failed: ", result->message);
        }
      } catch (const std::exception& e) {
        beft::log::error("request ", request.request_id, ": ", e.what());
      }
    }
  }
  beft::log::info("stopping after ", answered, " answers");
  return 0;
}
