#include "experts/exploration/exploration_expert.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <beft/run_status_t.hpp>

#include "lib/common/channels.hpp"
#include "lib/common/log.hpp"
#include "lib/task/task_commands.hpp"
#include "lib/wire/obstacle_map_codec.hpp"

namespace beft::exploration {
namespace {

constexpr double kNoLimit = DeclaredParameters::kNoLimit;

}  // namespace

HypothesisView viewOf(const hypothesis_t& h, const dynamic_weights_t* weights) {
  HypothesisView view;
  view.object_id = h.object_id;
  view.x = h.x;
  view.y = h.y;
  view.located = h.located;
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
  if (request.type == TaskRequest::Type::Push) {
    tasks::Task task;
    task.parent = request.parent;
    task.kind = request.kind;
    task.priority = request.priority;
    task.x = request.x;
    task.y = request.y;
    task.yaw = request.yaw;
    task.object_id = request.object_id;
    task.origin = origin;
    task.note = request.note;
    return tasks::pushCommand(task, 0, 0);
  }
  // Ending an owned task: a pop naming it, with the outcome and the reason.
  const auto outcome = request.success ? tasks::Status::Done : tasks::Status::Failed;
  return tasks::popCommand(request.task_id, outcome, request.reason, origin, 0, 0);
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
         "explores frontiers (reachable free cells next to unknown ones), then visits the known free ground "
         "the camera has not yet had in view within close_look_m (a silent person lying in a house is "
         "perceived only then). When nothing is left, or the scenario's duration is reached, it publishes STOP_REQUEST with the reason. Reads GT_OBJECTS "
         "only for the scenario's duration. Deterministic.";
}

void ExplorationExpert::declareParameters(DeclaredParameters& parameters) {
  ExplorerParameters& e = parameters_;
  ViewpointParameters& v = e.viewpoints;
  FrontierParameters& f = e.frontiers;
  parameters.declare("verify_priority", e.verify_priority, 0, 1000000, "priority of verify tasks");
  parameters.declare("explore_priority", e.explore_priority, 0, 1000000, "priority of explore tasks (look around, frontiers)");
  parameters.declare("safety_margin_m", e.safety_margin_m, 0, kNoLimit, "added to the robot radius for where it may stand [m]");
  parameters.declare("look_around", e.look_around, "turn a full circle at the start");
  parameters.declare("verify_attempts", e.verify_attempts, 1, 1000, "viewpoints tried per heard hypothesis before giving up");
  parameters.declare("give_up_in_plain_view", e.give_up_in_plain_view,
                     "give a heard hypothesis up after a look that had its estimate in plain view and did not settle it");
  parameters.declare("verify_located_first", e.verify_located_first,
                     "verify a heard hypothesis not yet located (only a bearing) once no frontier and no ground to "
                     "look at closely is left; a located one at once");
  parameters.declare("inspect_attempts", e.inspect_attempts, 1, 1000, "viewpoints tried per glimpsed hypothesis");
  parameters.declare("ruled_out_viewpoints", e.ruled_out_viewpoints, 1, 1000,
                     "viewpoints of a hypothesis the map rules out on the way (a wall mapped in the line of sight) "
                     "before any look from elsewhere, up to which it is not given up; once looked at, a ruled-out "
                     "viewpoint counts as an attempt");
  parameters.declare("ruled_out_while_mapping", e.ruled_out_while_mapping, 0, 1000,
                     "viewpoints ruled out while a frontier lies within max_view_m of the target (the walls around "
                     "it still being mapped) that do not count against ruled_out_viewpoints, at most");
  parameters.declare("moved_m", e.moved_m, 0, kNoLimit,
                     "a hypothesis placed this much farther from where its viewpoints were tried than the robot "
                     "moved since is tried afresh (a heard estimate that jumped); one given up, once no frontier is "
                     "left and if placed this far from where it was when given up (0: never) [m]");
  parameters.declare("tries_after_moving", e.tries_after_moving, 0, 1000,
                     "times a hypothesis is tried afresh after it moved, at most");
  parameters.declare("inspect_glimpsed", e.inspect_glimpsed, "approach hypotheses glimpsed by vision that may be persons");
  parameters.declare("look_dwell_s", e.look_dwell_s, 0, kNoLimit, "after looking, wait this long for fusion to settle [s]");
  parameters.declare("attempt_timeout_s", e.attempt_timeout_s, 0, kNoLimit,
                     "an attempt fails after this plus travel / nominal_speed [s]", true);
  parameters.declare("nominal_speed", e.nominal_speed, 0, kNoLimit, "speed used to scale attempt timeouts [m/s]", true);
  parameters.declare("retry_after_s", e.retry_after_s, 0, kNoLimit,
                     "a hypothesis without a viewpoint is reconsidered after this [s]");
  parameters.declare("weight_gain_m", e.weight_gain_m, 0, kNoLimit,
                     "travel a DW weight of 1 is worth when choosing a hypothesis [m]");
  parameters.declare("min_view_m", v.min_distance_m, 0, kNoLimit, "closest viewpoint to a target [m]");
  parameters.declare("max_view_m", v.max_distance_m, 0, kNoLimit, "farthest viewpoint from a target [m]", true);
  parameters.declare("preferred_view_m", v.preferred_distance_m, 0, kNoLimit, "viewpoints farther than this cost extra [m]");
  parameters.declare("target_radius_m", v.target_radius_m, 0, kNoLimit,
                     "the sight lines to both sides of the target must be clear [m]");
  parameters.declare("target_clearance_m", v.target_clearance_m, 0, kNoLimit,
                     "occupied cells this close to the target are its own [m]");
  parameters.declare("car_extent_m", e.car_extent_m, 0, kNoLimit,
                     "occupied cells connected to a car and this close to it are its body, not in its way [m]");
  parameters.declare("fire_extent_m", e.fire_extent_m, 0, kNoLimit,
                     "occupied cells connected to a fire and this close to it are its body, not in its way [m]");
  parameters.declare("unknown_cost", v.unknown_cost, 0, kNoLimit, "cost per metre of sight line through unknown cells [m/m]");
  parameters.declare("tried_radius_m", v.tried_radius_m, 0, kNoLimit, "a new viewpoint keeps this far from tried ones [m]");
  parameters.declare("blind_radius_m", f.blind_radius_m, 0, kNoLimit,
                     "unknown ground this close to where the robot stood is no frontier [m]");
  parameters.declare("visited_radius_m", f.visited_radius_m, 0, kNoLimit,
                     "frontier cells this close to a reached frontier goal are ignored [m]");
  parameters.declare("min_frontier_cells", f.min_cells, 1, 1000000, "smaller frontiers are ignored [cells]");
  CloseLookParameters& c = e.close_looks;
  parameters.declare("close_look", c.enabled,
                     "once no frontier is left, visit the known free ground the camera has not seen within "
                     "close_look_m and in view (a person lying there is seen only that close)");
  parameters.declare("close_look_m", c.range_m, 0.5, kNoLimit, "ground this close to the camera, in view, is looked at closely [m]");
  parameters.declare("close_look_fov_deg", c.fov_deg, 1, 179, "the camera's horizontal field of view for close looks [deg]");
  parameters.declare("close_look_min_cells", c.min_cells, 1, 1000000,
                     "smaller patches of ground not looked at closely are ignored [0.5 m cells]");
  parameters.declare("close_look_hidden_near_goal_m", c.hidden_near_goal_m, 0, kNoLimit,
                     "ground a close look's goal could not see, hidden by what stands this near the goal, stays to "
                     "be looked at from elsewhere; hidden by what stands farther, within close_look_m, it is given "
                     "up (0: all of it, faster but a house's floor seen only from its open side may be missed) [m]");
  parameters.declare("stop_when_done", e.stop_when_done,
                     "request the stop when nothing is left (0: keep watching until the scenario's duration)");
}

void ExplorationExpert::onStartUp() {
  if (parameters_.viewpoints.max_distance_m <= parameters_.viewpoints.min_distance_m)
    throw std::invalid_argument("max_view_m must be greater than min_view_m");
  parameters_.origin = name();
  explorer_ = std::make_unique<Explorer>(parameters_);
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
    o.head_yaw = robot->head_yaw;
    if (robot->radius > 0) o.robot_radius = robot->radius;
  }
  const auto* weights = weights_.ofTick(firing.tick);
  if (weights == nullptr) weights = weights_.latest();
  const auto* hypotheses = hypotheses_.ofTick(firing.tick);
  if (hypotheses == nullptr) hypotheses = hypotheses_.latest();
  if (hypotheses != nullptr)
    for (const auto& h : hypotheses->hypotheses) o.hypotheses.push_back(viewOf(h, weights));

  // Made only when the explorer will look at it this step.
  if (explorer_->wantsMap(o.t)) {
    try {
      auto map = map_messages_.ofTick(firing.tick);
      if (map == nullptr) map = map_messages_.latest();
      if (map != nullptr && map != map_) {  // unchanged: the same map, nothing to redo
        map_ = std::move(map);
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
  if (!explorer_) startUp();
  const Observation observation = observe(firing);
  if (!observation.robot_known)
    return expert::Outcome::failure("no ROBOT_STATE for tick " + std::to_string(firing.tick));
  const Decision decision = explorer_->step(observation);
  for (const auto& line : decision.log) log::info(line);
  for (const auto& request : decision.requests) {
    task_command_t command = commandOf(request, parameters_.origin);
    command.utime = firing.utime;
    command.command_id = next_command_id_++;
    task_command_out_.publish(out, command);
  }
  if (decision.stop) {
    run_status_t stop{};
    stop.utime = firing.utime;
    stop.tick = firing.tick;
    stop.state = run_status_t::STATE_FINISHED;
    stop.message = *decision.stop;
    stop_request_out_.publish(out, stop);
  }
  return expert::Outcome::success();
}

}  // namespace beft::exploration
