#include "tasks_expert.hpp"

#include <cmath>

#include <beft/task_events_t.hpp>
#include <beft/task_stack_t.hpp>

#include "channels.hpp"
#include "log.hpp"
#include "task_messages.hpp"

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
         "in arrival order. Publishes ROBOT_CMD and TASK_STACK every firing, TASK_EVENTS when a "
         "task changes (assigned ids, ends and their reasons).";
}

std::vector<expert::ChannelSpec> TasksExpert::reads() const {
  return {{channels::kTaskCommand, "beft.task_command_t"},
          {channels::kRobotState, "beft.robot_state_t"},
          {channels::kHypotheses, "beft.hypotheses_t"},
          {channels::kAudio, "beft.acoustic_percepts_t"},
          {channels::kObstacleMap, "beft.obstacle_map_t"},
          {channels::kPlanResult, "beft.plan_result_t"}};
}

std::vector<expert::ChannelSpec> TasksExpert::writes() const {
  return {{channels::kRobotCommand, "beft.robot_command_t"},
          {channels::kTaskStack, "beft.task_stack_t"},
          {channels::kTaskEvents, "beft.task_events_t"},
          {channels::kPlanRequest, "beft.plan_request_t"}};
}

std::vector<std::vector<std::string>> TasksExpert::parameterHelp() const {
  const ExecutorParameters d;
  const auto s = [](double v) {
    std::string text = std::to_string(v);
    text.erase(text.find_last_not_of('0') + 1);
    if (!text.empty() && text.back() == '.') text.pop_back();
    return text;
  };
  return {{"waypoint_tolerance_m", s(d.waypoint_tolerance_m), "a waypoint counts as reached within this [m]"},
          {"goal_tolerance_m", s(d.goal_tolerance_m), "goto is done within this of its goal [m]"},
          {"yaw_tolerance_deg", s(d.yaw_tolerance_deg), "goto and turn are done within this heading error [deg]"},
          {"head_tolerance_deg", s(d.head_tolerance_deg), "turn_head is done within this [deg]"},
          {"look_tolerance_deg", s(d.look_tolerance_deg), "look_at is done with the object within this of the nose [deg]"},
          {"look_hold_s", s(d.look_hold_s), "look_at keeps facing the object this long before it is done [s]"},
          {"head_yaw_limit_deg", s(d.head_yaw_limit_deg), "head pan range, +- around the nose [deg]"},
          {"max_failed_plans", std::to_string(d.max_failed_plans), "goto fails after this many failed plans in a row"},
          {"max_replans", std::to_string(d.max_replans), "goto fails after this many collisions or stalls"},
          {"backoff_m", s(d.backoff_m), "after a collision, goto backs away this far before replanning [m]"},
          {"stall_s", s(d.stall_s), "no progress for this long: goto replans, turns fail [s]"},
          {"look_timeout_s", s(d.look_timeout_s), "look_at fails after this long [s]"},
          {"owned_idle_s", s(d.owned_idle_s), "an owned task on top with no sub-task for this long fails [s]"},
          {"plan_time_budget_s", s(d.plan_time_budget_s), "time budget sent with each plan request [s]"},
          {"planner", "", "planner name sent with each plan request (empty: the service's default)"},
          {"goto_centres_head", "1", "goto turns the head to the front so the camera maps the way"},
          {"child_failure_fails_parent", "1", "a failed sub-task fails its parent (0: the parent resumes)"},
          {"max_tasks", "256", "pushes beyond this many tasks are rejected"}};
}

void TasksExpert::onStartUp(const expert::Parameters& p) {
  ExecutorParameters e;
  e.waypoint_tolerance_m = p.getDouble("waypoint_tolerance_m", e.waypoint_tolerance_m);
  e.goal_tolerance_m = p.getDouble("goal_tolerance_m", e.goal_tolerance_m);
  e.yaw_tolerance_deg = p.getDouble("yaw_tolerance_deg", e.yaw_tolerance_deg);
  e.head_tolerance_deg = p.getDouble("head_tolerance_deg", e.head_tolerance_deg);
  e.look_tolerance_deg = p.getDouble("look_tolerance_deg", e.look_tolerance_deg);
  e.look_hold_s = p.getDouble("look_hold_s", e.look_hold_s);
  e.head_yaw_limit_deg = p.getDouble("head_yaw_limit_deg", e.head_yaw_limit_deg);
  e.max_failed_plans = static_cast<int>(p.getInt("max_failed_plans", e.max_failed_plans));
  e.max_replans = static_cast<int>(p.getInt("max_replans", e.max_replans));
  e.backoff_m = p.getDouble("backoff_m", e.backoff_m);
  e.stall_s = p.getDouble("stall_s", e.stall_s);
  e.look_timeout_s = p.getDouble("look_timeout_s", e.look_timeout_s);
  e.owned_idle_s = p.getDouble("owned_idle_s", e.owned_idle_s);
  e.plan_time_budget_s = p.getDouble("plan_time_budget_s", e.plan_time_budget_s);
  e.planner = p.getString("planner", e.planner);
  e.goto_centres_head = p.getBool("goto_centres_head", e.goto_centres_head);
  const auto positive = [](double v, const char* name) {
    if (!(v > 0) || !std::isfinite(v)) throw std::invalid_argument(std::string(name) + " must be > 0");
  };
  positive(e.waypoint_tolerance_m, "waypoint_tolerance_m");
  positive(e.goal_tolerance_m, "goal_tolerance_m");
  positive(e.yaw_tolerance_deg, "yaw_tolerance_deg");
  positive(e.head_tolerance_deg, "head_tolerance_deg");
  positive(e.look_tolerance_deg, "look_tolerance_deg");
  positive(e.head_yaw_limit_deg, "head_yaw_limit_deg");
  positive(e.stall_s, "stall_s");
  positive(e.look_timeout_s, "look_timeout_s");
  positive(e.owned_idle_s, "owned_idle_s");
  positive(e.plan_time_budget_s, "plan_time_budget_s");
  if (e.look_hold_s < 0) throw std::invalid_argument("look_hold_s must be >= 0");
  if (!(e.backoff_m >= 0 && e.backoff_m <= 5)) throw std::invalid_argument("backoff_m must be in [0, 5]");
  if (e.max_failed_plans < 1) throw std::invalid_argument("max_failed_plans must be >= 1");
  if (e.max_replans < 0) throw std::invalid_argument("max_replans must be >= 0");
  StackOptions options;
  options.child_failure_fails_parent = p.getBool("child_failure_fails_parent", true);
  const int64_t max_tasks = p.getInt("max_tasks", 256);
  if (max_tasks < 1) throw std::invalid_argument("max_tasks must be >= 1");
  options.max_tasks = static_cast<std::size_t>(max_tasks);
  stack_ = std::make_unique<TaskStack>(options);
  executor_ = std::make_unique<Executor>(e);
}

bool TasksExpert::onMessage(const std::string& channel, const void* data, int size) {
  if (channel == channels::kTaskCommand) {
    task_command_t command;
    if (!expert::decodeMessage(data, size, command)) return false;
    if (commands_.size() < kMaxQueuedCommands) commands_.push_back(std::move(command));
    else ++dropped_commands_;
    return true;
  }
  if (channel == channels::kPlanResult) {
    plan_result_t result;
    if (!expert::decodeMessage(data, size, result)) return false;
    plan_results_.push_back(std::move(result));
    while (plan_results_.size() > 16) plan_results_.pop_front();
    return true;
  }
  if (channel == channels::kRobotState) return robot_.store(data, size);
  if (channel == channels::kHypotheses) return hypotheses_.store(data, size);
  if (channel == channels::kAudio) return audio_.store(data, size);
  if (channel == channels::kObstacleMap) return map_.store(data, size);
  return false;
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

  if (const auto* map = map_.latest(); map != nullptr && map->utime != map_utime_) {
    map_utime_ = map->utime;
    try {
      if (!last_map_ || !planners::sameEncodedMap(*map, *last_map_)) {  // unchanged: nothing to decode
        executor_->setObstacleMap(planners::decodeObstacleMap(*map));
        last_map_ = *map;
      }
    } catch (const std::exception& e) {
      if (!map_warned_) log::warn("OBSTACLE_MAP ignored: ", e.what());
      map_warned_ = true;
    }
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
  if (!stack_) onStartUp({});
  std::vector<task_command_t> commands;
  commands.swap(commands_);
  if (dropped_commands_ > 0) {
    log::warn("dropped ", dropped_commands_, " TASK_COMMANDs beyond ", kMaxQueuedCommands, " queued in one tick");
    dropped_commands_ = 0;
  }
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

  if (result.request) out.publish(channels::kPlanRequest, *result.request);
  result.command.utime = firing.utime;
  out.publish(channels::kRobotCommand, result.command);
  out.publish(channels::kTaskStack, stackMessage(*stack_, firing.utime, firing.tick));
  if (!events.empty()) out.publish(channels::kTaskEvents, eventsMessage(events, firing.utime, firing.tick));
  // Late inputs are not the stack's failure (a failure would make the arbiter
  // retry the tick): it ran on the latest robot state it had, and says so.
  if (robot_.ofTick(firing.tick) == nullptr)
    log::warn("tick ", firing.tick, ": no ROBOT_STATE of this tick, ran on the latest one");
  return expert::Outcome::success();
}

}  // namespace beft::tasks
