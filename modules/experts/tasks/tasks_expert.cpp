#include "experts/tasks/tasks_expert.hpp"

#include <algorithm>
#include <cmath>

#include <beft/task_events_t.hpp>
#include <beft/task_stack_t.hpp>

#include "lib/common/channels.hpp"
#include "lib/common/log.hpp"
#include "lib/task/task_messages.hpp"

namespace beft::tasks {

std::string TasksExpert::description() const {
  return "The task stack and its executor (paper section 2.3). Holds tasks ordered by priority, "
         "top first; a higher-priority push interrupts the top, which resumes afterwards. Built-in "
         "kinds: goto X Y YAW (plans through the planner service on PLAN_REQUEST/PLAN_RESULT, then "
         "drives the waypoints with ROBOT_CMD set-points; replans after a collision or when the "
         "obstacle map blocks the path), turn_head YAW, turn YAW, look_at OBJECT (head, and the "
         "platform beyond the head's range; position from HYPOTHESES or AUDIO), wait SECONDS. Any "
         "other kind (approach, verify, explore, ...) is owned by the expert that pushed it: it "
         "pushes sub-tasks (parent_id) and ends it with a TASK_COMMAND pop naming its task_id. "
         "Commands come on TASK_COMMAND (from experts or beft-task) and apply at the next firing, "
         "ordered by their task's origin (the sender's name), then by arrival. Publishes ROBOT_CMD and TASK_STACK every firing, TASK_EVENTS when a "
         "task changes (assigned ids, ends and their reasons).";
}

void TasksExpert::declareParameters(DeclaredParameters& parameters) {
  ExecutorParameters& e = executor_parameters_;
  constexpr double kNoLimit = DeclaredParameters::kNoLimit;
  const auto positive = [&](const char* name, double& member, const char* meaning) {
    parameters.declare(name, member, 0, kNoLimit, meaning, true);
  };
  positive("waypoint_tolerance_m", e.waypoint_tolerance_m, "a waypoint counts as reached within this [m]");
  positive("goal_tolerance_m", e.goal_tolerance_m, "goto is done within this of its goal [m]");
  positive("yaw_tolerance_deg", e.yaw_tolerance_deg, "goto and turn are done within this heading error [deg]");
  positive("head_tolerance_deg", e.head_tolerance_deg, "turn_head is done within this [deg]");
  positive("look_tolerance_deg", e.look_tolerance_deg, "look_at is done with the object within this of the nose [deg]");
  parameters.declare("look_hold_s", e.look_hold_s, 0, kNoLimit, "look_at keeps facing the object this long before it is done [s]");
  positive("head_yaw_limit_deg", e.head_yaw_limit_deg, "head pan range, +- around the nose [deg]");
  parameters.declare("max_failed_plans", e.max_failed_plans, 1, 1000000, "goto fails after this many failed plans in a row");
  parameters.declare("max_replans", e.max_replans, 0, 1000000, "goto fails after this many collisions or stalls");
  parameters.declare("backoff_m", e.backoff_m, 0, 5, "after a collision, goto backs away this far before replanning [m]");
  parameters.declare("path_clearance_margin_m", e.path_clearance_margin_m, 0, 1,
                     "a path nearer a newly mapped obstacle than the robot radius and this is replanned [m]");
  positive("stall_s", e.stall_s, "no progress for this long: goto replans, turns fail [s]");
  positive("look_timeout_s", e.look_timeout_s, "look_at fails after this long [s]");
  positive("owned_idle_s", e.owned_idle_s, "an owned task on top with no sub-task for this long fails [s]");
  positive("plan_time_budget_s", e.plan_time_budget_s, "time budget sent with each plan request [s]");
  parameters.declare("planner", e.planner, "planner name sent with each plan request (empty: the service's default)");
  parameters.declare("goto_looks_ahead", e.goto_looks_ahead,
                     "goto turns the head to where the path goes (look_ahead_m ahead) so the camera maps the way");
  positive("look_ahead_m", e.look_ahead_m, "goto looks at the path this far ahead [m]");
  parameters.declare("look_before_moving_deg", e.look_before_moving_deg, 1, 180,
                     "goto drives only while the camera looks within this of the way ahead, else turns on the spot [deg]");
  parameters.declare("max_contacts_at_place", e.max_contacts_at_place, 1, 1000,
                     "goto fails (blocked) after this many contacts at one place");
  positive("contact_place_m", e.contact_place_m, "contacts within this of each other count as one place [m]");
  parameters.declare("child_failure_fails_parent", stack_options_.child_failure_fails_parent,
                     "a failed sub-task fails its parent (0: the parent resumes)");
  parameters.declare("max_tasks", stack_options_.max_tasks, 1, 1000000, "pushes beyond this many tasks are rejected");
}

void TasksExpert::onStartUp() {
  stack_ = std::make_unique<TaskStack>(stack_options_);
  executor_ = std::make_unique<Executor>(executor_parameters_);
}

void TasksExpert::onCommand(task_command_t&& command) {
  if (commands_.size() < kMaxQueuedCommands) commands_.push_back(std::move(command));
  else ++dropped_commands_;
}

void TasksExpert::onPlanResult(plan_result_t&& result) {
  plan_results_.push_back(std::move(result));
  while (plan_results_.size() > 16) plan_results_.pop_front();
}

bool TasksExpert::inputsReady(const expert::Firing& firing) const {
  if (!robot_.has(firing.tick)) return false;
  if (!executor_) return true;
  const int64_t awaited = executor_->awaitedRequest();
  if (awaited == 0) return true;
  for (const auto& result : plan_results_)
    if (result.request_id == awaited) return true;
  return false;
}

void TasksExpert::applyCommand(const task_command_t& command) {
  switch (command.command) {
    case task_command_t::COMMAND_PUSH: {
      Task task = fromMessage(command.task);
      if (task.origin.empty()) task.origin = "?";
      if (task.note.empty()) task.note = describe(task);
      stack_->push(task, command.command_id);
      break;
    }
    case task_command_t::COMMAND_POP: {
      const int64_t id = command.task.task_id;
      if (id == 0) {
        if (!stack_->pop(command.command_id))
          stack_->reject(fromMessage(command.task), "pop: the stack is empty", command.command_id);
        break;
      }
      bool found;
      const std::string& reason = command.task.note;
      if (command.task.status == task_t::STATUS_DONE)
        found = stack_->finish(id, Status::Done, reason, command.command_id);
      else if (command.task.status == task_t::STATUS_FAILED)
        found = stack_->finish(id, Status::Failed, reason, command.command_id);
      else
        found = stack_->remove(id, reason.empty() ? "removed" : reason, command.command_id);
      if (!found)
        stack_->reject(fromMessage(command.task), "pop: no task " + std::to_string(id) + " on the stack",
                       command.command_id);
      break;
    }
    case task_command_t::COMMAND_CLEAR:
      stack_->clear(command.command_id);
      break;
    default:
      stack_->reject(fromMessage(command.task), "unknown command " + std::to_string(command.command),
                     command.command_id);
  }
}

void TasksExpert::updateExecutorInputs(const expert::Firing& firing) {
  const auto* robot = robot_.ofTick(firing.tick);
  if (robot == nullptr) robot = robot_.latest();
  if (robot != nullptr) executor_->setRobotState(*robot);

  // Where objects are: the fused hypotheses first, the acoustic estimates for the rest.
  std::map<std::string, std::pair<double, double>> positions;
  if (const auto* audio = audio_.latest())
    for (const auto& p : audio->percepts) positions[p.object_id] = {p.est_x, p.est_y};
  if (const auto* hypotheses = hypotheses_.latest())
    for (const auto& h : hypotheses->hypotheses) positions[h.object_id] = {h.x, h.y};
  executor_->setObjectPositions(std::move(positions));

  try {
    // Decoded once per change; the version grows only when cells changed.
    if (const auto map = map_.latest(); map != nullptr) {
      executor_->setObstacleMap(map, map_.version() != map_version_);
      map_version_ = map_.version();
    }
  } catch (const std::exception& e) {
    if (!map_warned_) log::warn("OBSTACLE_MAP ignored: ", e.what());
    map_warned_ = true;
  }

  const int64_t awaited = executor_->awaitedRequest();
  for (const auto& result : plan_results_)
    if (result.request_id == awaited) executor_->onPlanResult(result);
}

void TasksExpert::logEvents(const std::vector<TaskEvent>& events) const {
  for (const auto& event : events) {
    if (event.kind == TaskEvent::Kind::Started || event.kind == TaskEvent::Kind::Suspended ||
        event.kind == TaskEvent::Kind::Resumed)
      continue;  // the executor's start/resume lines say it
    const bool bad = event.kind == TaskEvent::Kind::Rejected || event.kind == TaskEvent::Kind::Failed;
    if (bad) log::warn(describeEvent(event));
    else log::info(describeEvent(event));
  }
}

expert::Outcome TasksExpert::fire(const expert::Firing& firing, expert::Output& out) {
  if (!stack_) startUp();
  std::vector<task_command_t> commands;
  commands.swap(commands_);
  if (dropped_commands_ > 0) {
    log::warn("dropped ", dropped_commands_, " TASK_COMMANDs beyond ", kMaxQueuedCommands, " queued in one tick");
    dropped_commands_ = 0;
  }
  // Two experts' commands of one tick arrive in the network's order (a lost
  // and repaired one comes last); their origin gives the run its own order.
  std::stable_sort(commands.begin(), commands.end(), [](const task_command_t& a, const task_command_t& b) {
    return a.task.origin < b.task.origin;
  });
  for (const auto& command : commands) applyCommand(command);
  std::vector<TaskEvent> events = stack_->takeEvents();
  logEvents(events);

  updateExecutorInputs(firing);
  Executor::TickOutput result = executor_->tick(*stack_, firing.utime);
  for (const auto& line : result.log) {
    if (line.rfind("failed ", 0) == 0) log::warn(line);
    else log::info(line);
  }
  const std::vector<TaskEvent> executor_events = stack_->takeEvents();  // the executor logged them
  events.insert(events.end(), executor_events.begin(), executor_events.end());

  if (result.request) plan_request_out_.publish(out, *result.request);
  result.command.utime = firing.utime;
  robot_command_out_.publish(out, result.command);
  task_stack_out_.publish(out, stackMessage(*stack_, firing.utime, firing.tick));
  if (!events.empty()) task_events_out_.publish(out, eventsMessage(events, firing.utime, firing.tick));
  // Late inputs are not the stack's failure (a failure would make the arbiter
  // retry the tick): it ran on the latest robot state it had, and says so.
  if (robot_.ofTick(firing.tick) == nullptr)
    log::warn("tick ", firing.tick, ": no ROBOT_STATE of this tick, ran on the latest one");
  return expert::Outcome::success();
}

}  // namespace beft::tasks
