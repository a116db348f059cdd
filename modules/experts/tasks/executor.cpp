#include "experts/tasks/executor.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "lib/model/model.hpp"

namespace beft::tasks {

namespace {

constexpr double kPi = 3.14159265358979323846;

double wrap(double deg) { return model::wrapDegrees(deg); }

std::string fmt(double value, int decimals = 2) {
  char buffer[48];
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, value);
  return buffer;
}

int64_t micros(double seconds) { return static_cast<int64_t>(std::llround(seconds * 1e6)); }

}  // namespace

double bearingDeg(double x0, double y0, double x1, double y1) {
  return std::atan2(y1 - y0, x1 - x0) * 180.0 / kPi;
}

Executor::Executor(ExecutorParameters parameters)
    : parameters_(std::move(parameters)), next_request_id_(parameters_.first_request_id) {}

void Executor::setObstacleMap(planners::ObstacleCells map) {
  setObstacleMap(std::make_shared<const planners::ObstacleCells>(std::move(map)));
}

void Executor::setObstacleMap(std::shared_ptr<const planners::ObstacleCells> map) {
  if (map == nullptr || map == map_) return;
  const bool same = map_ && map_->width == map->width && map_->height == map->height &&
                    map_->resolution == map->resolution && map_->origin_x == map->origin_x &&
                    map_->origin_y == map->origin_y && map_->cells == map->cells;
  setObstacleMap(std::move(map), !same);
}

void Executor::setObstacleMap(std::shared_ptr<const planners::ObstacleCells> map, bool cells_changed) {
  if (map == nullptr) return;
  map_ = std::move(map);  // the same cells too: the one before is let go
  if (cells_changed) map_changed_ = true;
}

void Executor::onPlanResult(const beft::plan_result_t& result) {
  if (awaited_request_ != 0 && result.request_id == awaited_request_) plan_result_ = result;
}

beft::robot_command_t Executor::hold(int64_t utime) const {
  beft::robot_command_t command{};
  command.utime = utime;
  command.mode = beft::robot_command_t::MODE_STOP;
  command.vx = command.vy = command.yaw_rate = 0;
  command.goal_x = robot_ ? robot_->x : 0;
  command.goal_y = robot_ ? robot_->y : 0;
  command.goal_yaw = robot_ ? robot_->yaw : 0;
  command.set_head = false;
  command.head_yaw = robot_ ? robot_->head_yaw : 0;
  command.head_pitch = robot_ ? robot_->head_pitch : 0;
  command.source = "tasks";
  return command;
}

beft::robot_command_t Executor::gotoCommand(double x, double y, double yaw, int64_t utime) const {
  beft::robot_command_t command = hold(utime);
  command.mode = beft::robot_command_t::MODE_GOTO;
  command.goal_x = x;
  command.goal_y = y;
  command.goal_yaw = yaw;
  return command;
}

bool Executor::stalled(Run& run, double error, double min_gain, int64_t utime) const {
  if (error < run.best_error - min_gain) {
    run.best_error = error;
    run.progress_utime = utime;
    return false;
  }
  return utime - run.progress_utime >= micros(parameters_.stall_s);
}

void Executor::forgetGoneTasks(const TaskStack& stack) {
  // Forget the tasks that left the stack, and an answer nobody waits for.
  for (auto it = runs_.begin(); it != runs_.end();)
    it = stack.find(it->first) == nullptr ? runs_.erase(it) : std::next(it);
  if (awaited_request_ != 0 &&
      std::none_of(runs_.begin(), runs_.end(),
                   [&](const auto& entry) { return entry.second.request_id == awaited_request_; })) {
    awaited_request_ = 0;
    plan_result_.reset();
  }
}

// Started, or resumed after an interruption: start the watches afresh from
// where the robot is now.
void Executor::startOrResume(const Task& task, Run& run, bool is_new, int64_t utime, TickOutput& out) {
  if (!is_new && task.kind == kinds::kGoto && !run.path.empty() && !run.need_plan &&
      std::hypot(robot_->x - run.hold_x, robot_->y - run.hold_y) > parameters_.waypoint_tolerance_m)
    run.need_plan = true;  // moved while suspended: the old path may not start here
  run.started_utime = utime;
  run.hold_x = robot_->x;
  run.hold_y = robot_->y;
  run.best_error = 1e300;
  run.progress_utime = utime;
  run.aligned_since = -1;
  run.turning_platform = false;
  run.idle_since = -1;
  if (is_new) run.collisions_seen = robot_->collisions;
  out.log.push_back(std::string(is_new ? "start " : "resume ") + std::to_string(task.id) + " " + describe(task) +
                    " (priority " + std::to_string(task.priority) + ", from " +
                    (task.origin.empty() ? "?" : task.origin) + ")");
}

Executor::Finish Executor::runTask(const Task& task, Run& run, int64_t utime, TickOutput& out) {
  if (task.kind == kinds::kTurnHead) return runTurnHead(task, run, utime, out);
  if (task.kind == kinds::kTurn) return runTurn(task, run, utime, out);
  if (task.kind == kinds::kLookAt) return runLookAt(task, run, utime, out);
  if (task.kind == kinds::kWait) return runWait(task, run, utime, out);
  if (task.kind != kinds::kGoto) return runOwned(task, run, utime, out);
  Finish finish = runGoto(task, run, utime, out);
  run.hold_x = robot_->x;  // where it was last active, to notice a move while suspended
  run.hold_y = robot_->y;
  return finish;
}

void Executor::finishTask(TaskStack& stack, const Task& task, const std::pair<Status, std::string>& finish,
                          TickOutput& out) {
  const std::size_t seen = stack.pendingEvents().size();
  stack.finish(task.id, finish.first, finish.second);
  for (std::size_t i = seen; i < stack.pendingEvents().size(); ++i) {
    const auto& event = stack.pendingEvents()[i];
    if (event.kind != TaskEvent::Kind::Started && event.kind != TaskEvent::Kind::Suspended &&
        event.kind != TaskEvent::Kind::Resumed)
      out.log.push_back(describeEvent(event));  // in order with the start/resume lines
  }
  runs_.erase(task.id);
}

Executor::TickOutput Executor::tick(TaskStack& stack, int64_t utime) {
  TickOutput out;
  out.command = hold(utime);

  forgetGoneTasks(stack);

  if (!robot_) {
    if (!warned_no_robot_ && !stack.empty())
      out.log.push_back("no ROBOT_STATE yet: holding every task");
    warned_no_robot_ = true;
    map_changed_ = false;
    return out;
  }

  // A finished task hands the tick to the next one, so a chain of instant
  // tasks does not cost a tick each; bounded so a tick always ends.
  for (int cascade = 0; cascade < 8; ++cascade) {
    const Task* top = stack.top();
    if (top == nullptr) {
      last_top_id_ = 0;
      break;
    }
    const Task task = *top;
    auto [it, is_new] = runs_.try_emplace(task.id);
    Run& run = it->second;
    if (is_new || last_top_id_ != task.id) startOrResume(task, run, is_new, utime, out);
    last_top_id_ = task.id;

    const Finish finish = runTask(task, run, utime, out);
    if (!finish) break;
    finishTask(stack, task, *finish, out);
    out.command = hold(utime);
    if (out.request) break;
  }
  map_changed_ = false;
  return out;
}

Executor::Finish Executor::collectPlan(const Task& task, Run& run, TickOutput& out) {
  const int64_t id = run.request_id;
  run.request_id = 0;
  awaited_request_ = 0;
  std::optional<beft::plan_result_t> result;
  result.swap(plan_result_);
  if (!result || result->request_id != id) {
    run.last_plan_error = "no answer from the planner service to request " + std::to_string(id) +
                          " (is beft-planner running on this LCM URL?)";
  } else if (!result->success) {
    run.last_plan_error = "planner " + (result->planner.empty() ? std::string("?") : result->planner) +
                          " found no path" + (result->message.empty() ? "" : ": " + result->message);
  } else if (result->waypoints.empty()) {
    run.last_plan_error = "planner " + result->planner + " answered with no waypoints";
  } else {
    run.path = result->waypoints;
    run.next_waypoint = 0;
    run.goal_moved = std::hypot(run.path.back().x - task.x, run.path.back().y - task.y) > parameters_.goal_tolerance_m;
    run.failed_plans = 0;
    run.need_plan = false;
    run.best_error = 1e300;
    out.log.push_back("path for " + std::to_string(task.id) + " " + describe(task) + ": " +
                      std::to_string(run.path.size()) + " waypoints, " + fmt(result->length) + " m (" +
                      result->planner + ", " + fmt(result->planning_time, 3) + " s)");
    return std::nullopt;
  }
  ++run.failed_plans;
  out.log.push_back("plan " + std::to_string(run.failed_plans) + "/" +
                    std::to_string(parameters_.max_failed_plans) + " for " + std::to_string(task.id) +
                    " failed: " + run.last_plan_error);
  if (run.failed_plans >= parameters_.max_failed_plans)
    return std::make_pair(Status::Failed, "no path after " + std::to_string(run.failed_plans) +
                                              " attempts: " + run.last_plan_error);
  run.need_plan = true;
  return std::nullopt;
}

void Executor::requestPlan(const Task& task, Run& run, int64_t utime, TickOutput& out) {
  const auto& r = *robot_;
  beft::plan_request_t request{};
  request.utime = utime;
  request.request_id = next_request_id_++;
  request.start_x = r.x;
  request.start_y = r.y;
  request.start_yaw = r.yaw;
  request.goal_x = task.x;
  request.goal_y = task.y;
  // Any final heading: arrive facing the way travelled.
  request.goal_yaw = std::isnan(task.yaw) ? bearingDeg(r.x, r.y, task.x, task.y) : task.yaw;
  request.planner = parameters_.planner;
  request.time_budget = parameters_.plan_time_budget_s;
  run.request_id = request.request_id;
  run.need_plan = false;
  awaited_request_ = request.request_id;
  plan_result_.reset();
  out.request = request;
  out.log.push_back("plan request " + std::to_string(request.request_id) + " for " +
                    std::to_string(task.id) + ": (" + fmt(r.x) + ", " + fmt(r.y) + ") -> (" +
                    fmt(task.x) + ", " + fmt(task.y) + ")");
}

// Blocked: a newly mapped obstacle closer to the path than the robot's
// radius and a margin (a stale path that grazes a wall by less than its
// tracking error touches it). Within near_robot_m of where the robot stands,
// where it may stand close to an obstacle it is leaving, only what is nearer
// than 0.9 radius counts.
bool Executor::pathBlocked(const Run& run) const {
  if (!map_ || run.path.empty() || map_->width <= 0 || map_->height <= 0) return false;
  const auto& r = *robot_;
  const auto& map = *map_;
  const double clearance = std::max(r.radius + parameters_.path_clearance_margin_m, map.resolution);
  const double near_clearance = std::max(0.9 * r.radius, map.resolution);
  constexpr double near_robot_m = 0.5;
  const int reach = static_cast<int>(std::ceil(clearance / map.resolution));
  const double step = map.resolution / 2;
  const auto& goal = run.path.back();
  // The cells within the clearance, once for every sample, with their distance.
  struct Offset {
    int dx, dy;
    double distance;
  };
  std::vector<Offset> disc;
  for (int dy = -reach; dy <= reach; ++dy)
    for (int dx = -reach; dx <= reach; ++dx) {
      const double distance = std::hypot(dx, dy) * map.resolution;
      if (distance <= clearance) disc.push_back({dx, dy, distance});
    }
  const auto occupiedNear = [&](double px, double py) {
    if (std::hypot(px - r.x, py - r.y) < 0.15) return false;  // where it stands now
    if (std::hypot(px - goal.x, py - goal.y) < r.radius) return false;  // the goal's own surroundings
    const double allowed = std::hypot(px - r.x, py - r.y) < near_robot_m ? near_clearance : clearance;
    const int cx = static_cast<int>(std::floor((px - map.origin_x) / map.resolution));
    const int cy = static_cast<int>(std::floor((py - map.origin_y) / map.resolution));
    for (const auto& offset : disc) {
      const int x = cx + offset.dx, y = cy + offset.dy;
      if (offset.distance > allowed || x < 0 || y < 0 || x >= map.width || y >= map.height) continue;
      if (map.at(x, y) == beft::obstacle_map_t::CELL_OCCUPIED) return true;
    }
    return false;
  };
  double ax = r.x, ay = r.y;
  for (std::size_t i = run.next_waypoint; i < run.path.size(); ++i) {
    const double bx = run.path[i].x, by = run.path[i].y;
    const double length = std::hypot(bx - ax, by - ay);
    const int samples = std::max(1, static_cast<int>(std::ceil(length / step)));
    for (int s = 0; s <= samples; ++s) {
      const double f = static_cast<double>(s) / samples;
      if (occupiedNear(ax + f * (bx - ax), ay + f * (by - ay))) return true;
    }
    ax = bx;
    ay = by;
  }
  return false;
}

// After a collision: back away from the contact, then plan afresh from
// clear ground (a start inside the inflated obstacle invites the same path).
// True while it still backs off (the command is set).
bool Executor::keepBackingOff(Run& run, int64_t utime, TickOutput& out) {
  const auto& r = *robot_;
  const bool touched = r.collisions > run.collisions_seen;
  run.collisions_seen = std::max(run.collisions_seen, r.collisions);
  if (std::hypot(run.backoff_x - r.x, run.backoff_y - r.y) < 0.05 || touched ||
      utime - run.backoff_utime >= micros(2.0)) {
    run.backing_off = false;
    run.need_plan = true;
    return false;
  }
  out.command = gotoCommand(run.backoff_x, run.backoff_y, r.yaw, utime);
  return true;
}

// While following a path: a collision, a newly mapped obstacle on the path
// or no progress asks for a new plan (too many: the goto fails); after a
// collision it backs off first (backing_off, the command set).
Executor::Finish Executor::watchPath(const Task& task, Run& run, int64_t utime, TickOutput& out, bool& backing_off) {
  const auto& r = *robot_;
  std::string why;
  const bool collided = r.collisions > run.collisions_seen;
  run.collisions_seen = std::max(run.collisions_seen, r.collisions);
  if (collided) {
    why = "the robot collided";
  } else if (map_changed_ && pathBlocked(run)) {
    // The map grows as the camera sees: not a failure, so not counted.
    out.log.push_back("replan " + std::to_string(task.id) + " " + describe(task) +
                      ": a newly mapped obstacle blocks the path");
    run.need_plan = true;
    run.best_error = 1e300;
    run.progress_utime = utime;
  }
  if (why.empty() && !run.need_plan) {
    // Progress: remaining path length plus the heading still to turn.
    const std::size_t n = run.path.size();
    const auto& target = run.path[std::min(run.next_waypoint, n - 1)];
    double remaining = std::hypot(target.x - r.x, target.y - r.y) +
                       std::abs(wrap(target.yaw - r.yaw)) / 90.0;
    for (std::size_t i = run.next_waypoint + 1; i < n; ++i)
      remaining += std::hypot(run.path[i].x - run.path[i - 1].x, run.path[i].y - run.path[i - 1].y);
    if (stalled(run, remaining, 0.05, utime))
      why = "no progress for " + fmt(parameters_.stall_s, 1) + " s";
  }
  if (collided) {
    const int at_this_place = 1 + static_cast<int>(std::count_if(
        run.contacts.begin(), run.contacts.end(), [&](const std::pair<double, double>& contact) {
          return std::hypot(contact.first - r.x, contact.second - r.y) <= parameters_.contact_place_m;
        }));
    run.contacts.emplace_back(r.x, r.y);
    if (at_this_place >= parameters_.max_contacts_at_place)
      return std::make_pair(Status::Failed, "blocked: " + std::to_string(at_this_place) + " contacts at (" +
                                                fmt(r.x) + ", " + fmt(r.y) + ")");
  }
  if (!why.empty()) {
    ++run.replans;
    if (run.replans > parameters_.max_replans)
      return std::make_pair(Status::Failed, "gave up after " + std::to_string(parameters_.max_replans) +
                                                " replans (last: " + why + ")");
    run.best_error = 1e300;
    run.progress_utime = utime;
    if (collided && parameters_.backoff_m > 0) {
      startBackoff(run, utime);
      out.log.push_back("replan " + std::to_string(task.id) + " " + describe(task) + ": " + why +
                        "; backing off " + fmt(parameters_.backoff_m) + " m first");
      out.command = gotoCommand(run.backoff_x, run.backoff_y, r.yaw, utime);
      backing_off = true;
      return std::nullopt;
    }
    out.log.push_back("replan " + std::to_string(task.id) + " " + describe(task) + ": " + why);
    run.need_plan = true;
  }
  return std::nullopt;
}

// Follows the path one waypoint at a time.
void Executor::followPath(const Task& task, Run& run, int64_t utime, TickOutput& out) {
  const auto& r = *robot_;
  const bool any_yaw = std::isnan(task.yaw);
  const std::size_t last = run.path.size() - 1;
  while (run.next_waypoint < last &&
         std::hypot(run.path[run.next_waypoint].x - r.x, run.path[run.next_waypoint].y - r.y) <
             parameters_.waypoint_tolerance_m)
    ++run.next_waypoint;
  const auto& waypoint = run.path[run.next_waypoint];
  if (run.next_waypoint == last && !run.goal_moved)
    out.command = gotoCommand(task.x, task.y, any_yaw ? waypoint.yaw : task.yaw, utime);
  else if (run.next_waypoint == last)  // not into the obstacle beside the goal: to the path's end
    out.command = gotoCommand(waypoint.x, waypoint.y, any_yaw ? waypoint.yaw : task.yaw, utime);
  else
    out.command = gotoCommand(waypoint.x, waypoint.y, waypoint.yaw, utime);
  run.setpoint_x = out.command.goal_x;
  run.setpoint_y = out.command.goal_y;
  rememberTrail(run);
  if (parameters_.goto_looks_ahead) lookAlongPath(run, out);
}

// The head turns to where the robot is about to drive, as a person looks
// where they walk: the way it drives now, leaning towards the point
// look_ahead_m along the path (by up to half of look_before_moving_deg, to see
// round a corner). Until the camera looks within look_before_moving_deg of the
// way it drives now, the platform only turns on the spot: it never drives into
// ground it has not seen.
void Executor::lookAlongPath(const Run& run, TickOutput& out) const {
  const auto& r = *robot_;
  const double to_setpoint = std::hypot(out.command.goal_x - r.x, out.command.goal_y - r.y);
  if (to_setpoint < 0.05) return;  // arriving: nothing ahead to see
  double ax = r.x, ay = r.y, left = parameters_.look_ahead_m;
  double look_x = ax, look_y = ay;
  for (std::size_t i = run.next_waypoint; i < run.path.size() && left > 0; ++i) {
    const double bx = run.path[i].x, by = run.path[i].y;
    const double length = std::hypot(bx - ax, by - ay);
    const double f = length > left ? left / length : 1.0;
    look_x = ax + f * (bx - ax);
    look_y = ay + f * (by - ay);
    left -= length;
    ax = bx;
    ay = by;
  }
  const double way_now = bearingDeg(r.x, r.y, out.command.goal_x, out.command.goal_y);
  const double lean = parameters_.look_before_moving_deg / 2;
  const double way_ahead = bearingDeg(r.x, r.y, look_x, look_y);
  const double gaze = way_now + std::clamp(wrap(way_ahead - way_now), -lean, lean);
  out.command.set_head = true;
  out.command.head_yaw =
      std::clamp(wrap(gaze - r.yaw), -parameters_.head_yaw_limit_deg, parameters_.head_yaw_limit_deg);
  out.command.head_pitch = 0;
  if (std::abs(wrap(way_now - (r.yaw + r.head_yaw))) > parameters_.look_before_moving_deg) {
    out.command.goal_x = r.x;
    out.command.goal_y = r.y;
    out.command.goal_yaw = way_now;
  }
}

// Ground the platform stood on lately: a way back that is known to be free.
void Executor::rememberTrail(Run& run) const {
  const auto& r = *robot_;
  if (!run.trail.empty() && std::hypot(run.trail.back().first - r.x, run.trail.back().second - r.y) < 0.1) return;
  run.trail.emplace_back(r.x, r.y);
  if (run.trail.size() > 64) run.trail.erase(run.trail.begin());
}

Executor::Finish Executor::runGoto(const Task& task, Run& run, int64_t utime, TickOutput& out) {
  const auto& r = *robot_;
  const bool any_yaw = std::isnan(task.yaw);
  // A goal the planner found blocked is reached at the path's end.
  const bool to_path_end = run.goal_moved && !run.path.empty();
  const double goal_x = to_path_end ? run.path.back().x : task.x, goal_y = to_path_end ? run.path.back().y : task.y;
  const double goal_distance = std::hypot(goal_x - r.x, goal_y - r.y);
  const double goal_yaw_error = any_yaw ? 0.0 : std::abs(wrap(task.yaw - r.yaw));
  if (run.request_id == 0 && goal_distance <= parameters_.goal_tolerance_m &&
      goal_yaw_error <= parameters_.yaw_tolerance_deg)
    return std::make_pair(Status::Done, "reached (" + fmt(r.x) + ", " + fmt(r.y) + ", " + fmt(r.yaw, 1) + ")" +
                                            (to_path_end ? ": the free cell nearest the blocked goal" : ""));

  if (run.backing_off && keepBackingOff(run, utime, out)) return std::nullopt;
  if (run.request_id != 0) {
    if (auto failed = collectPlan(task, run, out)) return failed;
  } else if (!run.need_plan) {
    bool backing_off = false;
    if (auto failed = watchPath(task, run, utime, out, backing_off)) return failed;
    if (backing_off) return std::nullopt;
  }
  if (run.need_plan) {
    requestPlan(task, run, utime, out);
    return std::nullopt;  // hold until the answer, next tick
  }

  followPath(task, run, utime, out);
  return std::nullopt;
}

void Executor::startBackoff(Run& run, int64_t utime) const {
  const auto& r = *robot_;
  // Back along its own trail (ground it stood on) when it has one that far.
  for (auto it = run.trail.rbegin(); it != run.trail.rend(); ++it) {
    if (std::hypot(it->first - r.x, it->second - r.y) >= parameters_.backoff_m) {
      run.backoff_x = it->first;
      run.backoff_y = it->second;
      run.backing_off = true;
      run.backoff_utime = utime;
      return;
    }
  }
  // Else away from where it was driving; straight back when it was not driving.
  double dx = r.x - run.setpoint_x, dy = r.y - run.setpoint_y;
  double length = std::hypot(dx, dy);
  if (length < 1e-6) {
    dx = -std::cos(r.yaw * kPi / 180);
    dy = -std::sin(r.yaw * kPi / 180);
    length = 1;
  }
  run.backoff_x = r.x + parameters_.backoff_m * dx / length;
  run.backoff_y = r.y + parameters_.backoff_m * dy / length;
  if (map_) {
    // The world refuses goals outside it: stay within the mapped area.
    const double margin = r.radius + map_->resolution;
    const double x0 = map_->origin_x + margin, x1 = map_->origin_x + map_->width * map_->resolution - margin;
    const double y0 = map_->origin_y + margin, y1 = map_->origin_y + map_->height * map_->resolution - margin;
    if (x0 < x1) run.backoff_x = std::clamp(run.backoff_x, x0, x1);
    if (y0 < y1) run.backoff_y = std::clamp(run.backoff_y, y0, y1);
  }
  run.backing_off = true;
  run.backoff_utime = utime;
}

Executor::Finish Executor::runTurnHead(const Task& task, Run& run, int64_t utime, TickOutput& out) {
  const auto& r = *robot_;
  const double limit = parameters_.head_yaw_limit_deg;
  const double target = std::clamp(wrap(task.yaw), -limit, limit);
  const double error = std::abs(wrap(target - r.head_yaw));
  const std::string clamped = target != wrap(task.yaw) ? " (limited to the head's range)" : "";
  if (error <= parameters_.head_tolerance_deg)
    return std::make_pair(Status::Done, "head at " + fmt(r.head_yaw, 1) + " deg" + clamped);
  if (stalled(run, error, 0.5, utime))
    return std::make_pair(Status::Failed, "the head stopped at " + fmt(r.head_yaw, 1) + " deg, target " +
                                              fmt(target, 1) + " deg");
  out.command = hold(utime);
  out.command.mode = beft::robot_command_t::MODE_HEAD_ONLY;
  out.command.set_head = true;
  out.command.head_yaw = target;
  out.command.head_pitch = r.head_pitch;
  return std::nullopt;
}

Executor::Finish Executor::runTurn(const Task& task, Run& run, int64_t utime, TickOutput& out) {
  const auto& r = *robot_;
  const double error = std::abs(wrap(task.yaw - r.yaw));
  if (error <= parameters_.yaw_tolerance_deg)
    return std::make_pair(Status::Done, "heading " + fmt(r.yaw, 1) + " deg");
  if (stalled(run, error, 0.5, utime))
    return std::make_pair(Status::Failed, "the platform stopped turning at " + fmt(r.yaw, 1) +
                                              " deg, target " + fmt(task.yaw, 1) + " deg");
  out.command = gotoCommand(run.hold_x, run.hold_y, wrap(task.yaw), utime);
  return std::nullopt;
}

Executor::Finish Executor::runLookAt(const Task& task, Run& run, int64_t utime, TickOutput& out) {
  const auto& r = *robot_;
  double ox, oy;
  const auto known = object_positions_.find(task.object_id);
  if (!task.object_id.empty() && known != object_positions_.end()) {
    ox = known->second.first;
    oy = known->second.second;
  } else if (std::isfinite(task.x) && std::isfinite(task.y)) {
    ox = task.x;
    oy = task.y;
  } else {
    return std::make_pair(Status::Failed, "the position of '" + task.object_id +
                                              "' is unknown (not in HYPOTHESES or AUDIO)");
  }
  const std::string what = task.object_id.empty() ? "(" + fmt(ox) + ", " + fmt(oy) + ")" : task.object_id;
  if (std::hypot(ox - r.x, oy - r.y) < 0.05) return std::make_pair(Status::Done, "standing at " + what);

  const double bearing = bearingDeg(r.x, r.y, ox, oy);
  const double relative = wrap(bearing - r.yaw);  // head yaw that would face it
  const double nose_error = std::abs(wrap(bearing - (r.yaw + r.head_yaw)));
  if (nose_error <= parameters_.look_tolerance_deg) {
    if (run.aligned_since < 0) run.aligned_since = utime;
    if (utime - run.aligned_since >= micros(parameters_.look_hold_s))
      return std::make_pair(Status::Done, "facing " + what + " (azimuth " + fmt(nose_error, 1) + " deg)");
  } else {
    run.aligned_since = -1;
  }
  if (utime - run.started_utime >= micros(parameters_.look_timeout_s))
    return std::make_pair(Status::Failed, "could not face " + what + " within " +
                                              fmt(parameters_.look_timeout_s, 1) + " s");

  const double limit = parameters_.head_yaw_limit_deg;
  // Beyond the head's range: turn the platform until it faces the object, the
  // head leading; once started, the platform turn goes on to the end so the
  // head ends near the centre of its range.
  if (std::abs(relative) > limit) run.turning_platform = true;
  // A head that stops short (a robot with a narrower pan range than
  // head_yaw_limit_deg) gets the platform's help too.
  if (!run.turning_platform && nose_error > parameters_.look_tolerance_deg) {
    if (nose_error < run.best_error - 0.5) {
      run.best_error = nose_error;
      run.progress_utime = utime;
    } else if (utime - run.progress_utime >= micros(1.0)) {
      run.turning_platform = true;
    }
  }
  if (run.turning_platform && std::abs(relative) <= parameters_.yaw_tolerance_deg)
    run.turning_platform = false;
  if (run.turning_platform) {
    out.command = gotoCommand(run.hold_x, run.hold_y, bearing, utime);
  } else {
    out.command = hold(utime);
    out.command.mode = beft::robot_command_t::MODE_HEAD_ONLY;
  }
  out.command.set_head = true;
  out.command.head_yaw = std::clamp(relative, -limit, limit);
  out.command.head_pitch = r.head_pitch;
  return std::nullopt;
}

Executor::Finish Executor::runWait(const Task& task, Run& run, int64_t utime, TickOutput& out) {
  out.command = hold(utime);
  if (utime - run.started_utime >= micros(task.x))
    return std::make_pair(Status::Done, "waited " + fmt(task.x, 1) + " s");
  return std::nullopt;
}

Executor::Finish Executor::runOwned(const Task& task, Run& run, int64_t utime, TickOutput& out) {
  // Its owner drives it by pushing sub-tasks and ends it; meanwhile hold still.
  out.command = hold(utime);
  if (run.idle_since < 0) run.idle_since = utime;
  if (utime - run.idle_since >= micros(parameters_.owned_idle_s))
    return std::make_pair(Status::Failed, "its owner '" + task.origin + "' pushed no sub-task and did not end it within " +
                                              fmt(parameters_.owned_idle_s, 1) + " s");
  return std::nullopt;
}

}  // namespace beft::tasks
