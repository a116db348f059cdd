#include "exploration_expert.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <beft/run_status_t.hpp>
#include <beft/task_t.hpp>

#include "channels.hpp"
#include "log.hpp"
#include "obstacle_map_codec.hpp"

namespace beft::exploration {
namespace {

std::string number(double value) {
  std::string text = std::to_string(value);
  text.erase(text.find_last_not_of('0') + 1);
  if (!text.empty() && text.back() == '.') text.pop_back();
  return text;
}

void requirePositive(double value, const char* name) {
  if (!(value > 0) || !std::isfinite(value)) throw std::invalid_argument(std::string(name) + " must be > 0");
}

void requireNonNegative(double value, const char* name) {
  if (!(value >= 0) || !std::isfinite(value)) throw std::invalid_argument(std::string(name) + " must be >= 0");
}

}  // namespace

HypothesisView viewOf(const hypothesis_t& h, const dynamic_weights_t* weights) {
  HypothesisView view;
  view.object_id = h.object_id;
  view.x = h.x;
  view.y = h.y;
  view.seen = h.seen;
  view.heard = h.heard;
  view.verified = h.verified;
  view.falsified = h.falsified;
  // Fusion keeps a hypothesis only for what was perceived: neither seen nor
  // heard means vision had pixels of it, too few to count as seen.
  view.glimpsed = !h.seen && !h.heard;
  view.best_category = h.best_category;
  view.confidence = h.confidence;
  const size_t n = std::min(h.categories.size(), h.fused.size());
  for (size_t i = 0; i < n; ++i)
    if (h.categories[i] == "person") view.person_confidence = h.fused[i];
  if (weights != nullptr)
    for (const auto& w : weights->weights)
      if (w.object_id == h.object_id) view.weight = w.weight;
  return view;
}

task_command_t commandOf(const TaskRequest& request, const std::string& origin) {
  task_command_t command{};
  command.task.origin = origin;
  if (request.type == TaskRequest::Type::Push) {
    command.command = task_command_t::COMMAND_PUSH;
    command.task.parent_id = request.parent;
    command.task.kind = request.kind;
    command.task.priority = request.priority;
    command.task.x = request.x;
    command.task.y = request.y;
    command.task.yaw = request.yaw;
    command.task.object_id = request.object_id;
    command.task.status = task_t::STATUS_PENDING;
    command.task.note = request.note;
  } else {
    // Ending an owned task: a pop naming it, with the outcome and the reason.
    command.command = task_command_t::COMMAND_POP;
    command.task.task_id = request.task_id;
    command.task.status = request.success ? task_t::STATUS_DONE : task_t::STATUS_FAILED;
    command.task.note = request.reason;
  }
  return command;
}

std::string ExplorationExpert::description() const {
  return "High-level exploration expert (active exploration). For each hypothesis heard but not "
         "settled (neither verified nor falsified by vision) it picks a viewpoint from which the known "
         "obstacle map gives a line of sight to it, that the robot can stand on and reach (unknown "
         "cells count as free), between min_view_m and max_view_m away, preferring short travel; it "
         "pushes a composite 'verify' task with the sub-tasks 'goto x y yaw' (facing the target) and "
         "'look_at object', ends it when fusion settles the hypothesis, and tries another viewpoint "
         "when the robot looked and it is still unsettled (up to verify_attempts). Glimpsed possible "
         "persons are inspected the same way. With nothing to check it looks around at the start and "
         "explores frontiers (reachable free cells next to unknown ones). When nothing is left, or the "
         "scenario's duration is reached, it publishes STOP_REQUEST with the reason. Reads GT_OBJECTS "
         "only for the scenario's duration. Deterministic.";
}

std::vector<expert::ChannelSpec> ExplorationExpert::reads() const {
  return {{channels::kHypotheses, "beft.hypotheses_t"},     {channels::kObstacleMap, "beft.obstacle_map_t"},
          {channels::kRobotState, "beft.robot_state_t"},    {channels::kTaskStack, "beft.task_stack_t"},
          {channels::kDynamicWeights, "beft.dynamic_weights_t"}, {channels::kGroundTruth, "beft.scene_objects_t"}};
}

std::vector<expert::ChannelSpec> ExplorationExpert::writes() const {
  return {{channels::kTaskCommand, "beft.task_command_t"}, {channels::kStopRequest, "beft.run_status_t"}};
}

std::vector<std::vector<std::string>> ExplorationExpert::parameterHelp() const {
  const ExplorerParameters d;
  return {
      {"verify_priority", std::to_string(d.verify_priority), "priority of verify tasks"},
      {"explore_priority", std::to_string(d.explore_priority), "priority of explore tasks (look around, frontiers)"},
      {"safety_margin_m", number(d.safety_margin_m), "added to the robot radius for where it may stand [m]"},
      {"look_around", "1", "turn a full circle at the start"},
      {"verify_attempts", std::to_string(d.verify_attempts), "viewpoints tried per heard hypothesis before giving up"},
      {"inspect_attempts", std::to_string(d.inspect_attempts), "viewpoints tried per glimpsed hypothesis"},
      {"inspect_glimpsed", "1", "approach hypotheses glimpsed by vision that may be persons"},
      {"look_dwell_s", number(d.look_dwell_s), "after looking, wait this long for fusion to settle [s]"},
      {"attempt_timeout_s", number(d.attempt_timeout_s), "an attempt fails after this plus travel / nominal_speed [s]"},
      {"nominal_speed", number(d.nominal_speed), "speed used to scale attempt timeouts [m/s]"},
      {"retry_after_s", number(d.retry_after_s), "a hypothesis without a viewpoint is reconsidered after this [s]"},
      {"weight_gain_m", number(d.weight_gain_m), "travel a DW weight of 1 is worth when choosing a hypothesis [m]"},
      {"min_view_m", number(d.viewpoints.min_distance_m), "closest viewpoint to a target [m]"},
      {"max_view_m", number(d.viewpoints.max_distance_m), "farthest viewpoint from a target [m]"},
      {"preferred_view_m", number(d.viewpoints.preferred_distance_m), "viewpoints farther than this cost extra [m]"},
      {"target_radius_m", number(d.viewpoints.target_radius_m), "the sight lines to both sides of the target must be clear [m]"},
      {"target_clearance_m", number(d.viewpoints.target_clearance_m), "occupied cells this close to the target are its own [m]"},
      {"unknown_cost", number(d.viewpoints.unknown_cost), "cost per metre of sight line through unknown cells [m/m]"},
      {"tried_radius_m", number(d.viewpoints.tried_radius_m), "a new viewpoint keeps this far from tried ones [m]"},
      {"blind_radius_m", number(d.frontiers.blind_radius_m), "unknown ground this close to where the robot stood is no frontier [m]"},
      {"visited_radius_m", number(d.frontiers.visited_radius_m), "frontier cells this close to a reached frontier goal are ignored [m]"},
      {"min_frontier_cells", std::to_string(d.frontiers.min_cells), "smaller frontiers are ignored [cells]"},
      {"stop_when_done", "1", "request the stop when nothing is left (0: keep watching until the scenario's duration)"},
  };
}

void ExplorationExpert::onStartUp(const expert::Parameters& p) {
  ExplorerParameters e;
  e.origin = name();
  e.verify_priority = static_cast<int32_t>(p.getInt("verify_priority", e.verify_priority));
  e.explore_priority = static_cast<int32_t>(p.getInt("explore_priority", e.explore_priority));
  e.safety_margin_m = p.getDouble("safety_margin_m", e.safety_margin_m);
  e.look_around = p.getBool("look_around", e.look_around);
  e.verify_attempts = static_cast<int>(p.getInt("verify_attempts", e.verify_attempts));
  e.inspect_attempts = static_cast<int>(p.getInt("inspect_attempts", e.inspect_attempts));
  e.inspect_glimpsed = p.getBool("inspect_glimpsed", e.inspect_glimpsed);
  e.look_dwell_s = p.getDouble("look_dwell_s", e.look_dwell_s);
  e.attempt_timeout_s = p.getDouble("attempt_timeout_s", e.attempt_timeout_s);
  e.nominal_speed = p.getDouble("nominal_speed", e.nominal_speed);
  e.retry_after_s = p.getDouble("retry_after_s", e.retry_after_s);
  e.weight_gain_m = p.getDouble("weight_gain_m", e.weight_gain_m);
  e.viewpoints.min_distance_m = p.getDouble("min_view_m", e.viewpoints.min_distance_m);
  e.viewpoints.max_distance_m = p.getDouble("max_view_m", e.viewpoints.max_distance_m);
  e.viewpoints.preferred_distance_m = p.getDouble("preferred_view_m", e.viewpoints.preferred_distance_m);
  e.viewpoints.target_radius_m = p.getDouble("target_radius_m", e.viewpoints.target_radius_m);
  e.viewpoints.target_clearance_m = p.getDouble("target_clearance_m", e.viewpoints.target_clearance_m);
  e.viewpoints.unknown_cost = p.getDouble("unknown_cost", e.viewpoints.unknown_cost);
  e.viewpoints.tried_radius_m = p.getDouble("tried_radius_m", e.viewpoints.tried_radius_m);
  e.frontiers.blind_radius_m = p.getDouble("blind_radius_m", e.frontiers.blind_radius_m);
  e.frontiers.visited_radius_m = p.getDouble("visited_radius_m", e.frontiers.visited_radius_m);
  e.frontiers.min_cells = static_cast<int>(p.getInt("min_frontier_cells", e.frontiers.min_cells));
  e.stop_when_done = p.getBool("stop_when_done", e.stop_when_done);

  requireNonNegative(e.safety_margin_m, "safety_margin_m");
  if (e.verify_attempts < 1) throw std::invalid_argument("verify_attempts must be >= 1");
  if (e.inspect_attempts < 1) throw std::invalid_argument("inspect_attempts must be >= 1");
  requireNonNegative(e.look_dwell_s, "look_dwell_s");
  requirePositive(e.attempt_timeout_s, "attempt_timeout_s");
  requirePositive(e.nominal_speed, "nominal_speed");
  requireNonNegative(e.retry_after_s, "retry_after_s");
  requireNonNegative(e.weight_gain_m, "weight_gain_m");
  requireNonNegative(e.viewpoints.min_distance_m, "min_view_m");
  requirePositive(e.viewpoints.max_distance_m, "max_view_m");
  if (e.viewpoints.max_distance_m <= e.viewpoints.min_distance_m)
    throw std::invalid_argument("max_view_m must be greater than min_view_m");
  requireNonNegative(e.viewpoints.preferred_distance_m, "preferred_view_m");
  requireNonNegative(e.viewpoints.target_radius_m, "target_radius_m");
  requireNonNegative(e.viewpoints.target_clearance_m, "target_clearance_m");
  requireNonNegative(e.viewpoints.unknown_cost, "unknown_cost");
  requireNonNegative(e.viewpoints.tried_radius_m, "tried_radius_m");
  requireNonNegative(e.frontiers.blind_radius_m, "blind_radius_m");
  requireNonNegative(e.frontiers.visited_radius_m, "visited_radius_m");
  if (e.frontiers.min_cells < 1) throw std::invalid_argument("min_frontier_cells must be >= 1");
  parameters_ = e;
  explorer_ = std::make_unique<Explorer>(parameters_);
}

bool ExplorationExpert::onMessage(const std::string& channel, const void* data, int size) {
  if (channel == channels::kRobotState) return robot_.store(data, size);
  if (channel == channels::kHypotheses) return hypotheses_.store(data, size);
  if (channel == channels::kDynamicWeights) return weights_.store(data, size);
  if (channel == channels::kObstacleMap) return map_messages_.store(data, size);
  if (channel == channels::kTaskStack) return stack_.store(data, size);
  if (channel == channels::kGroundTruth) return scene_.store(data, size);
  return false;
}

bool ExplorationExpert::inputsReady(const expert::Firing& firing) const {
  if (!robot_.has(firing.tick)) return false;
  // The experts before this one in the tick, once they have been heard from.
  if (!hypotheses_.empty() && !hypotheses_.has(firing.tick)) return false;
  if (!weights_.empty() && !weights_.has(firing.tick)) return false;
  if (!map_messages_.empty() && !map_messages_.has(firing.tick)) return false;
  // The stack of the previous tick (the task stack fires last), while it publishes.
  if (const auto* stack = stack_.latest();
      stack != nullptr && stack->tick >= firing.tick - 2 && stack->tick < firing.tick - 1)
    return false;
  return true;
}

Observation ExplorationExpert::observe(const expert::Firing& firing) {
  Observation o;
  o.t = firing.utime * 1e-6;
  if (const auto* scene = scene_.latest()) o.duration = scene->duration;
  const auto* robot = robot_.ofTick(firing.tick);
  if (robot == nullptr) robot = robot_.latest();
  if (robot != nullptr) {
    o.robot_known = true;
    o.robot_x = robot->x;
    o.robot_y = robot->y;
    o.robot_yaw = robot->yaw;
    if (robot->radius > 0) o.robot_radius = robot->radius;
  }
  const auto* weights = weights_.ofTick(firing.tick);
  if (weights == nullptr) weights = weights_.latest();
  const auto* hypotheses = hypotheses_.ofTick(firing.tick);
  if (hypotheses == nullptr) hypotheses = hypotheses_.latest();
  if (hypotheses != nullptr)
    for (const auto& h : hypotheses->hypotheses) o.hypotheses.push_back(viewOf(h, weights));

  const auto* map = map_messages_.ofTick(firing.tick);
  if (map == nullptr) map = map_messages_.latest();
  // Decoded only when the explorer will look at it this step.
  if (map != nullptr && map->utime != map_utime_ && explorer_->wantsMap(o.t)) {
    map_utime_ = map->utime;
    try {
      if (!last_map_ || !planners::sameEncodedMap(*map, *last_map_)) {  // unchanged: nothing to redo
        map_ = std::make_shared<const planners::ObstacleCells>(planners::decodeObstacleMap(*map));
        last_map_ = *map;
        ++map_version_;
      }
    } catch (const std::exception& e) {
      if (!map_warned_) log::warn("OBSTACLE_MAP ignored: ", e.what());
      map_warned_ = true;
    }
  }
  o.map = map_;
  o.map_version = map_version_;

  if (const auto* stack = stack_.latest()) {
    o.stack_known = true;
    for (const auto& task : stack->tasks)
      o.stack.push_back({task.task_id, task.parent_id, task.kind, task.object_id, task.origin, task.status});
  }
  return o;
}

expert::Outcome ExplorationExpert::fire(const expert::Firing& firing, expert::Output& out) {
  if (!explorer_) onStartUp({});
  const Observation observation = observe(firing);
  if (!observation.robot_known)
    return expert::Outcome::failure("no ROBOT_STATE for tick " + std::to_string(firing.tick));
  const Decision decision = explorer_->step(observation);
  for (const auto& line : decision.log) log::info(line);
  for (const auto& request : decision.requests) {
    task_command_t command = commandOf(request, parameters_.origin);
    command.utime = firing.utime;
    command.command_id = next_command_id_++;
    out.publish(channels::kTaskCommand, command);
  }
  if (decision.stop) {
    run_status_t stop{};
    stop.utime = firing.utime;
    stop.tick = firing.tick;
    stop.state = run_status_t::STATE_FINISHED;
    stop.message = *decision.stop;
    out.publish(channels::kStopRequest, stop);
  }
  return expert::Outcome::success();
}

}  // namespace beft::exploration
