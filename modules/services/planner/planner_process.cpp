#include "services/planner/planner_process.hpp"

#include <chrono>
#include <map>

#include <CLI/CLI.hpp>
#include <beft/obstacle_map_t.hpp>
#include <beft/plan_result_t.hpp>
#include <beft/run_status_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include "lib/common/channels.hpp"
#include "lib/transport/control_messages.hpp"
#include "lib/wire/encoded_stamp.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/common/log.hpp"
#include "lib/wire/log_reader.hpp"
#include "planners/ompl_planner.hpp"
#include "planners/planner_factory.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::planner_service {

namespace {

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

int64_t wallMicros() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace

std::string PlannerProcess::description() const {
  return "The planner service: plans on the robot's current obstacle map (OBSTACLE_MAP: what the camera has "
         "seen so far; unknown cells count as free) and answers each PLAN_REQUEST (start, goal, planner, time "
         "budget; world metres) once on PLAN_RESULT with sparse waypoints, each with its heading of travel and "
         "the goal heading at the end. Obstacles are inflated by the robot radius.";
}

void PlannerProcess::addOptions(CLI::App& app) {
  namespace bp = beft::planners;
  app.add_option("--planner", config_.default_planner, "planner for requests that name none: " + joined(bp::plannerNames()))
      ->capture_default_str();
  app.add_option("--robot-radius", config_.robot_radius, "obstacle inflation [m]")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--default-budget", config_.default_budget, "time budget of requests without one [s]")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_flag("--wall-clock-deadline", config_.wall_clock_deadline,
               "the time budget also cuts the grid planners (pf*, astar); off: they run to their own bounds, so a "
               "lockstep run's plans do not depend on the machine's load (OMPL's planners always stop on the budget)");
  app.add_option("--goal-snap", config_.goal_snap, "how far a blocked goal may move to a free cell [m]")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--seed", config_.seed, "seed of randomised planners (plus the request id)")->capture_default_str();
  app.add_option("--param", pf_params_,
                 "potential-field parameter name=value, repeatable: " + joined(bp::PotentialFieldParams::names()));
}

void PlannerProcess::onStartUp() {
  for (const auto& p : pf_params_) config_.pf_params.push_back(planners::splitParameter(p));
  planners::seedOmpl(config_.seed);
  planner_ = std::make_unique<PlannerService>(config_);
}

void PlannerProcess::keep(std::deque<KeptMessage>& kept, std::size_t most, const transport::Message& message) {
  KeptMessage kept_message{0, 0, std::vector<uint8_t>(message.data, message.data + message.size)};
  wire::encodedUtime(message.data, message.size, kept_message.utime);
  wire::encodedTick(message.data, message.size, kept_message.tick);
  while (!kept.empty() && kept.back().utime >= kept_message.utime) kept.pop_back();  // a tick sent again
  kept.push_back(std::move(kept_message));
  if (kept.size() > most) kept.pop_front();
}

void PlannerProcess::onRunStatus(const beft::run_status_t& status) {
  if (status.state == beft::run_status_t::STATE_WAITING) arbiter_waiting_ = true;
}

std::shared_ptr<const planners::ObstacleCells> PlannerProcess::mapFor(const beft::plan_request_t& request) {
  // Of the newest tick not after the request (or the oldest kept): the
  // changes of that tick on their keyframe, or a keyframe of that tick.
  auto newestUpTo = [&request](const std::deque<KeptMessage>& kept) -> const KeptMessage* {
    if (kept.empty()) return nullptr;
    for (auto it = kept.rbegin(); it != kept.rend(); ++it)
      if (it->utime <= request.utime) return &*it;
    return &kept.front();
  };
  const KeptMessage* changes_bytes = newestUpTo(recent_changes_);
  const KeptMessage* keyframe_bytes = newestUpTo(recent_keyframes_);
  if (keyframe_bytes == nullptr) return nullptr;
  beft::obstacle_map_changes_t changes{};
  const bool with_changes = changes_bytes != nullptr && changes_bytes->utime >= keyframe_bytes->utime;
  if (with_changes) {
    if (!changes_in_.decode(changes_bytes->bytes, changes))
      throw planners::ObstacleMapError("not an obstacle_map_changes_t");
    keyframe_bytes = nullptr;
    for (const auto& kept : recent_keyframes_)
      if (kept.tick == changes.keyframe_tick) keyframe_bytes = &kept;
    if (keyframe_bytes == nullptr)
      throw planners::ObstacleMapError("no keyframe of tick " + std::to_string(changes.keyframe_tick) +
                                       " for the changes of tick " + std::to_string(changes.tick));
  }
  beft::obstacle_map_t keyframe{};
  if (!keyframes_in_.decode(keyframe_bytes->bytes, keyframe))
    throw planners::ObstacleMapError("not an obstacle_map_t");
  return assembler_.mapOf(keyframe, with_changes ? &changes : nullptr);
}

void PlannerProcess::useMap(const std::shared_ptr<const planners::ObstacleCells>& map) {
  if (map == nullptr || map == map_in_use_) return;
  map_in_use_ = map;
  planner_->setObstacleMap(map);
}

void PlannerProcess::answerRequests(lcm::LCM& lcm) {
  while (!requests_.empty()) {
    const beft::plan_request_t request = requests_.front();
    requests_.pop_front();
    try {
      useMap(mapFor(request));
    } catch (const std::exception& e) {
      log::warn("ignoring a malformed obstacle map: ", e.what());
    }
    answerOne(lcm, request);
  }
}

void PlannerProcess::answerOne(lcm::LCM& lcm, const beft::plan_request_t& request) {
  try {
    auto result = planner_->handle(request, wallMicros());
    if (!result) {
      log::debug("request ", request.request_id, " was answered before; ignored");
      return;
    }
    results_out_.publish(lcm, *result);
    ++answered_;
    if (result->success)
      log::info("request ", request.request_id, " (", result->planner, "): ", result->num_waypoints,
                " waypoints, ", result->length, " m, ", 1000 * result->planning_time, " ms",
                result->message.empty() ? "" : " - " + result->message);
    else
      log::warn("request ", request.request_id, " (", result->planner, ") failed: ", result->message);
  } catch (const std::exception& e) {
    log::error("request ", request.request_id, ": ", e.what());
  }
}

void PlannerProcess::resumeFromLog(const std::string& log_path, int64_t live_since_us) {
  // What was sent before this process listened is in the log once the
  // recorder, which may lag, has written anything newer.
  if (!wire::waitForLogPast(log_path, live_since_us, 5.0))
    log::warn("the run's log ", log_path, " has nothing newer than this restart after 5 s: "
              "resuming from what it holds");
  // Each unanswered request with the map that was newest when it was sent,
  // as a live request would have been answered.
  std::map<int64_t, UnansweredRequest> unanswered;
  wire::LogReader log(log_path);
  wire::LogEvent event;
  while (log.nextOfRun(event, wire::runId())) {
    transport::Message message{event.channel.c_str(), event.data.data(), event.data.size()};
    if (event.channel == channels::kObstacleMap || event.channel == channels::kObstacleMapChanges) {
      dispatch(message);
    } else if (event.channel == channels::kPlanRequest) {
      beft::plan_request_t request{};
      if (wire::decodeFrom(event.channel, event.data.data(), event.data.size(), request)) {
        std::shared_ptr<const planners::ObstacleCells> map;
        try {
          map = mapFor(request);
        } catch (const std::exception& e) {
          log::warn("ignoring a malformed obstacle map: ", e.what());
        }
        unanswered.emplace(request.request_id, UnansweredRequest{request, map});
      }
    } else if (event.channel == channels::kPlanResult) {
      beft::plan_result_t result{};
      if (wire::decodeFrom(event.channel, event.data.data(), event.data.size(), result)) {
        unanswered.erase(result.request_id);
        planner_->markAnswered(result.request_id);
      }
    }
  }
  for (auto& [id, request] : unanswered) unanswered_.push_back(std::move(request));
  log::info("resumed from ", log_path, ": ", unanswered_.size(), " request(s) to answer",
            recent_keyframes_.empty() ? ", no map yet" : ", each with the map of its tick",
            log.damage().any() ? " (log: " + log.damage().summary() + ")" : "");
}

void PlannerProcess::answerUnanswered(lcm::LCM& lcm) {
  for (auto& unanswered : unanswered_) {
    useMap(unanswered.map);
    answerOne(lcm, unanswered.request);
  }
  unanswered_.clear();
}

int PlannerProcess::serve(service::Context& context) {
  // On udpm the maps (one a tick) queue on a socket nothing waits on and are
  // read when a request comes; requests wake the process.
  const transport::Selection maps = selection(service::Delivery::kQueued);
  const transport::Selection requests = selection(service::Delivery::kWakes);
  transport::SplitReceivers sources;
  try {
    sources = transport::openSplitReceivers(context.lcm, context.lcm_url, requests, maps, 16, 1000);
  } catch (const std::exception& e) {
    log::error("cannot receive on ", context.lcm_url, ": ", e.what());
    return 1;
  }
  if (sources.queued) log::info("maps: ", sources.queued->description());
  log::info("requests: ", sources.wake->description());
  log::info("planning with ", config_.default_planner, " (robot radius ", config_.robot_radius, " m) on ",
            context.lcm_url);
  const int64_t live_since_us = wallMicros();
  const transport::Handler to_inbox = [this](const transport::Message& m) { dispatch(m); };
  if (!context.resume_log.empty()) {
    try {
      resumeFromLog(context.resume_log, live_since_us);
    } catch (const std::exception& e) {
      log::error("cannot resume from ", context.resume_log, ": ", e.what());
      return 1;
    }
    answerUnanswered(context.lcm);
  }
  service::HeartbeatSender heartbeats(context.lcm, heartbeat_out_, context.process_name);
  while (!context.stop.any()) {
    heartbeats.update(arbiter_waiting_);
    arbiter_waiting_ = false;
    transport::waitReadable({sources.wake->fd()}, 100);
    // The maps around the requests: a request sees the map sent before it.
    if (transport::drainSplit(*sources.wake, sources.queued.get(), to_inbox) < 0) {
      if (context.stop.any()) break;  // interrupted by the stop signal
      log::error("LCM receive failed");
      return 1;
    }
    answerRequests(context.lcm);
  }
  log::info("stopping after ", answered_, " answers");
  return 0;
}

}  // namespace beft::planner_service
