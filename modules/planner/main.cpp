// beft-planner: the planner service. Subscribes OBSTACLE_MAP and
// PLAN_REQUEST, answers each request once on PLAN_RESULT, and sends a
// HEARTBEAT every second.
#include "channels.hpp"
#include "lcm_url.hpp"
#include "log.hpp"
#include "ompl_planner.hpp"
#include "planner_factory.hpp"
#include "planner_service.hpp"
#include "udpm_filter.hpp"

#include <beft/heartbeat_t.hpp>
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
class Inbox {
 public:
  void onMap(const lcm::ReceiveBuffer*, const std::string&, const beft::obstacle_map_t* msg) {
    latest_map = *msg;
    has_map = true;
  }
  void onRequest(const lcm::ReceiveBuffer*, const std::string&, const beft::plan_request_t* msg) {
    requests.push_back(*msg);
  }
  beft::obstacle_map_t latest_map;
  bool has_map = false;
  std::deque<beft::plan_request_t> requests;
};

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

}  // namespace

int main(int argc, char** argv) {
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
  Inbox inbox;
  lcm.subscribe(beft::channels::kObstacleMap, &Inbox::onMap, &inbox)->setQueueCapacity(4);
  lcm.subscribe(beft::channels::kPlanRequest, &Inbox::onRequest, &inbox)->setQueueCapacity(1000);
  beft::udpm_filter::Spec filter;
  filter.rules = {beft::udpm_filter::channelRule(beft::channels::kObstacleMap),
                  beft::udpm_filter::channelRule(beft::channels::kPlanRequest)};
  beft::udpm_filter::installAndReport(lcm, lcm_url, filter);
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
  int64_t answered = 0;
  while (!g_stop) {
    if (std::chrono::steady_clock::now() >= next_heartbeat) {
      heartbeat.utime = wallMicros();
      heartbeat.state = "idle";
      lcm.publish(beft::channels::kHeartbeat, &heartbeat);
      next_heartbeat += std::chrono::seconds(1);
    }
    if (lcm.handleTimeout(100) < 0) {
      if (g_stop) break;  // interrupted by the stop signal
      beft::log::error("LCM receive failed");
      return 1;
    }
    while (lcm.handleTimeout(0) > 0) {
    }  // take everything queued, so a request sees the map sent before it
    // Decoded only when a request needs it: the map arrives every tick, requests rarely.
    if (inbox.has_map && !inbox.requests.empty()) {
      try {
        service->setObstacleMap(inbox.latest_map);
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
