// The task executor: turns the top task of the stack into the robot's motion,
// one tick at a time. Motion primitives (goto, turn_head, turn, look_at, wait)
// run here; any other kind is a composite task owned by the expert that
// pushed it (see task.hpp), which the executor only holds still under.
//
// goto plans through the planner service asynchronously but deterministically:
// in the tick it needs a path, tick() returns a plan request and holds the
// robot; the answer must be handed to onPlanResult() before the next tick
// (the process waits for it, bounded), and is used then. A missing answer
// counts as a failed plan; after max_failed_plans the task fails.
// Plain logic, no LCM.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <beft/plan_request_t.hpp>
#include <beft/plan_result_t.hpp>
#include <beft/robot_command_t.hpp>
#include <beft/robot_state_t.hpp>

#include "lib/wire/obstacle_map_codec.hpp"
#include "lib/task/task_stack.hpp"

namespace beft::tasks {

struct ExecutorParameters {
  double waypoint_tolerance_m = 0.1;  // a waypoint counts as reached within this (small: no corner cutting)
  double goal_tolerance_m = 0.1;      // goto is done within this of its goal
  double yaw_tolerance_deg = 5;       // goto (with a yaw) and turn are done within this
  double head_tolerance_deg = 2;      // turn_head is done within this
  double look_tolerance_deg = 3;      // look_at is done when the object is within this of the nose
  double look_hold_s = 0.5;           // and stays there this long (simulated time)
  double head_yaw_limit_deg = 85;     // head pan range is +- this around the nose
  int max_failed_plans = 3;           // goto fails after this many failed plans in a row
  int max_replans = 10;               // goto fails after this many collisions or stalls
  double backoff_m = 0.3;             // after a collision, back away this far before replanning
  double path_clearance_margin_m = 0.1;   // a path nearer a mapped obstacle than the radius and this is blocked [m]
  double stall_s = 5;                 // no progress for this long: replan (goto) or fail
  double look_timeout_s = 20;         // look_at fails after this long
  double owned_idle_s = 10;           // an owned task with no sub-task for this long fails
  double plan_time_budget_s = 1.0;    // sent with each plan request
  std::string planner;                // planner name sent with each request, empty = default
  int64_t first_request_id = 1000000001;  // request ids count up from here
  bool goto_looks_ahead = true;       // goto turns the head to where the path goes, so the camera maps the way
  double look_ahead_m = 2.0;          // ... this far ahead along the path [m]
  double look_before_moving_deg = 30; // drives only while the camera looks within this of the way ahead [deg]
  int max_contacts_at_place = 2;      // goto fails after this many contacts at one place
  double contact_place_m = 0.6;       // contacts within this of each other are at one place [m]
};

class Executor {
 public:
  explicit Executor(ExecutorParameters parameters = {});

  // Inputs, stored until the next tick().
  void setRobotState(const beft::robot_state_t& state) { robot_ = state; }
  // Where an object is believed to be (hypotheses, else acoustic estimates).
  void setObjectPositions(std::map<std::string, std::pair<double, double>> positions) {
    object_positions_ = std::move(positions);
  }
  // The latest obstacle map; a change that blocks the current path replans.
  void setObstacleMap(planners::ObstacleCells map);
  // The same, shared: a map of two million cells is not copied. Compared
  // with the map before to tell whether it changed, unless the caller knows
  // (cells_changed: ObstacleMapInput's version, which compares only where
  // the maps can differ).
  void setObstacleMap(std::shared_ptr<const planners::ObstacleCells> map);
  void setObstacleMap(std::shared_ptr<const planners::ObstacleCells> map, bool cells_changed);
  // An answer of the planner service; kept only if it answers the request in flight.
  void onPlanResult(const beft::plan_result_t& result);

  // The plan request waiting for its answer (0 if none), and whether it came.
  int64_t awaitedRequest() const { return awaited_request_; }
  bool awaitedResultArrived() const { return plan_result_.has_value(); }

  struct TickOutput {
    beft::robot_command_t command{};                 // the whole desired motion
    std::optional<beft::plan_request_t> request;   // to publish on PLAN_REQUEST
    std::vector<std::string> log;                  // what happened, for the process log
  };
  // Advances the top task of the stack by one tick at simulated time utime:
  // finishes it (Done/Failed) when it ends, and says what the robot must do.
  TickOutput tick(TaskStack& stack, int64_t utime);

 private:
  // The executor's memory of one task; dropped when the task leaves the stack.
  struct Run {
    int64_t started_utime = 0;
    double hold_x = 0, hold_y = 0;       // where the platform stays while the task turns it
    // goto
    std::vector<beft::waypoint_t> path;
    std::size_t next_waypoint = 0;
    // The planner moved a blocked goal to the nearest free cell: the path
    // ends there, and the goto ends when the robot does.
    bool goal_moved = false;
    bool need_plan = true;
    int64_t request_id = 0;              // in flight
    int failed_plans = 0;
    int replans = 0;                     // after collisions or stalls
    int32_t collisions_seen = 0;
    double setpoint_x = 0, setpoint_y = 0;  // where it was last sent
    bool backing_off = false;
    double backoff_x = 0, backoff_y = 0;
    std::vector<std::pair<double, double>> contacts;  // where the robot stood at each contact
    std::vector<std::pair<double, double>> trail;     // where it drove lately (free ground), newest last
    int64_t backoff_utime = 0;
    std::string last_plan_error;
    // progress watch (goto, turns)
    double best_error = 1e300;
    int64_t progress_utime = 0;
    // look_at
    int64_t aligned_since = -1;
    bool turning_platform = false;
    // owned
    int64_t idle_since = -1;
  };

  using Finish = std::optional<std::pair<Status, std::string>>;
  void forgetGoneTasks(const TaskStack& stack);
  void startOrResume(const Task& task, Run& run, bool is_new, int64_t utime, TickOutput& out);
  Finish runTask(const Task& task, Run& run, int64_t utime, TickOutput& out);
  void finishTask(TaskStack& stack, const Task& task, const std::pair<Status, std::string>& finish, TickOutput& out);
  Finish runGoto(const Task& task, Run& run, int64_t utime, TickOutput& out);
  bool keepBackingOff(Run& run, int64_t utime, TickOutput& out);
  Finish watchPath(const Task& task, Run& run, int64_t utime, TickOutput& out, bool& backing_off);
  void followPath(const Task& task, Run& run, int64_t utime, TickOutput& out);
  void lookAlongPath(const Run& run, TickOutput& out) const;
  void rememberTrail(Run& run) const;
  Finish runTurnHead(const Task& task, Run& run, int64_t utime, TickOutput& out);
  Finish runTurn(const Task& task, Run& run, int64_t utime, TickOutput& out);
  Finish runLookAt(const Task& task, Run& run, int64_t utime, TickOutput& out);
  Finish runWait(const Task& task, Run& run, int64_t utime, TickOutput& out);
  Finish runOwned(const Task& task, Run& run, int64_t utime, TickOutput& out);

  // Takes the answer to the request in flight, or notes it never came.
  Finish collectPlan(const Task& task, Run& run, TickOutput& out);
  void requestPlan(const Task& task, Run& run, int64_t utime, TickOutput& out);
  bool pathBlocked(const Run& run) const;
  void startBackoff(Run& run, int64_t utime) const;
  // Records progress (a smaller error); true when stalled for stall_s.
  bool stalled(Run& run, double error, double min_gain, int64_t utime) const;

  beft::robot_command_t hold(int64_t utime) const;
  beft::robot_command_t gotoCommand(double x, double y, double yaw, int64_t utime) const;

  ExecutorParameters parameters_;
  std::optional<beft::robot_state_t> robot_;
  std::map<std::string, std::pair<double, double>> object_positions_;
  std::shared_ptr<const planners::ObstacleCells> map_;
  bool map_changed_ = false;
  std::map<int64_t, Run> runs_;
  int64_t next_request_id_;
  int64_t awaited_request_ = 0;
  std::optional<beft::plan_result_t> plan_result_;
  int64_t last_top_id_ = 0;  // the task run last tick, to notice a start or a resume
  bool warned_no_robot_ = false;
};

// Bearing from (x0, y0) to (x1, y1), CCW from +x [deg].
double bearingDeg(double x0, double y0, double x1, double y1);

}  // namespace beft::tasks
