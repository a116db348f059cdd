// The task executor against a scripted planner and a small kinematic robot:
// goto follows the waypoints to the goal, replans after a collision or when a
// newly mapped obstacle blocks the path, fails cleanly without a planner; the
// other primitives, interruption and owned composite tasks.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "experts/tasks/executor.hpp"
#include "lib/model/model.hpp"

namespace beft::tasks {
namespace {

constexpr int64_t kTickUs = 100000;  // dt = 0.1 s
constexpr double kPi = 3.14159265358979323846;

struct Disc {
  double x, y, r;
};

// A robot that does what ROBOT_CMD says, at fixed rates, and stops at contact.
class FakeRobot {
 public:
  FakeRobot() {
    state.x = state.y = state.yaw = 0;
    state.head_yaw = state.head_pitch = 0;
    state.radius = 0.3;
    state.collisions = 0;
    state.collided = false;
  }
  void apply(const beft::robot_command_t& c, double dt) {
    state.collided = false;
    if (c.set_head)
      state.head_yaw = std::clamp(state.head_yaw + limited(c.head_yaw - state.head_yaw, 180 * dt), -head_limit,
                                  head_limit);
    if (c.mode != beft::robot_command_t::MODE_GOTO) return;
    const double dx = c.goal_x - state.x, dy = c.goal_y - state.y;
    const double distance = std::hypot(dx, dy);
    if (distance > 0.01) {
      state.yaw = std::atan2(dy, dx) * 180 / kPi;
      const double step = std::min(distance, 1.0 * dt);
      const double nx = state.x + step * dx / distance, ny = state.y + step * dy / distance;
      for (const auto& d : obstacles)
        if (std::hypot(nx - d.x, ny - d.y) < d.r + state.radius) {
          state.collided = true;
          ++state.collisions;
          return;
        }
      state.path_length += step;
      state.x = nx;
      state.y = ny;
    } else {
      state.yaw += limited(model::wrapDegrees(c.goal_yaw - state.yaw), 90 * dt);
    }
  }
  static double limited(double delta, double max) { return std::clamp(delta, -max, max); }

  beft::robot_state_t state{};
  std::vector<Disc> obstacles;
  double head_limit = 85;  // pan range +- [deg]
};

beft::plan_result_t answer(const beft::plan_request_t& request, std::vector<std::array<double, 3>> points,
                           bool success = true) {
  beft::plan_result_t result{};
  result.utime = request.utime;
  result.request_id = request.request_id;
  result.success = success;
  result.planner = "scripted";
  result.length = 0;
  result.planning_time = 0.001;
  result.message = success ? "" : "goal is inside an obstacle";
  for (const auto& p : points) {
    beft::waypoint_t w{};
    w.x = p[0];
    w.y = p[1];
    w.yaw = p[2];
    result.waypoints.push_back(w);
  }
  result.num_waypoints = static_cast<int32_t>(result.waypoints.size());
  return result;
}

struct Harness {
  explicit Harness(ExecutorParameters p = {}) : executor(p) {}

  // One tick: the executor decides from the robot state, the planner answers
  // any request before the next tick, the robot applies the command.
  void step() {
    robot.state.utime = utime;
    executor.setRobotState(robot.state);
    auto out = executor.tick(stack, utime);
    for (auto& e : stack.takeEvents()) events.push_back(e);
    for (auto& line : out.log) log.push_back(line);
    commands.push_back(out.command);
    if (out.request) {
      requests.push_back(*out.request);
      if (planner)
        if (auto result = planner(*out.request)) executor.onPlanResult(*result);
    }
    robot.apply(out.command, kTickUs / 1e6);
    utime += kTickUs;
  }
  void run(int ticks) {
    for (int i = 0; i < ticks && !stack.empty(); ++i) step();
  }
  const TaskEvent* lastEventOf(int64_t id) const {
    for (auto it = events.rbegin(); it != events.rend(); ++it)
      if (it->task.id == id) return &*it;
    return nullptr;
  }

  TaskStack stack;
  Executor executor;
  FakeRobot robot;
  int64_t utime = 0;
  std::function<std::optional<beft::plan_result_t>(const beft::plan_request_t&)> planner;
  std::vector<beft::plan_request_t> requests;
  std::vector<beft::robot_command_t> commands;
  std::vector<TaskEvent> events;
  std::vector<std::string> log;
};

Task gotoTask(double x, double y, double yaw, int priority = 10) {
  Task t;
  t.kind = kinds::kGoto;
  t.x = x;
  t.y = y;
  t.yaw = yaw;
  t.priority = priority;
  t.origin = "test";
  return t;
}

TEST(Executor, GotoPlansThenFollowsTheWaypointsToTheGoal) {
  Harness h;
  h.planner = [](const beft::plan_request_t& r) {
    return answer(r, {{r.start_x, r.start_y, 0}, {4, 0, 0}, {4, 3, 90}});
  };
  const int64_t id = h.stack.push(gotoTask(4, 3, 90));
  h.step();
  ASSERT_EQ(h.requests.size(), 1u);
  EXPECT_DOUBLE_EQ(h.requests[0].start_x, 0);
  EXPECT_DOUBLE_EQ(h.requests[0].goal_x, 4);
  EXPECT_DOUBLE_EQ(h.requests[0].goal_y, 3);
  EXPECT_DOUBLE_EQ(h.requests[0].goal_yaw, 90);
  EXPECT_EQ(h.requests[0].request_id, ExecutorParameters{}.first_request_id);
  EXPECT_EQ(h.commands[0].mode, beft::robot_command_t::MODE_STOP) << "holds while the plan is computed";

  h.run(200);
  ASSERT_TRUE(h.stack.empty());
  const TaskEvent* end = h.lastEventOf(id);
  ASSERT_NE(end, nullptr);
  EXPECT_EQ(end->kind, TaskEvent::Kind::Done) << end->reason;
  EXPECT_NEAR(h.robot.state.x, 4, 0.2);
  EXPECT_NEAR(h.robot.state.y, 3, 0.2);
  EXPECT_NEAR(h.robot.state.yaw, 90, 5);
  EXPECT_EQ(h.requests.size(), 1u);
  // The set-points went to the corner waypoint first, then to the goal.
  std::size_t first_corner = 0, first_goal = 0;
  for (std::size_t i = 0; i < h.commands.size(); ++i) {
    const auto& c = h.commands[i];
    if (c.mode != beft::robot_command_t::MODE_GOTO) continue;
    if (!first_corner && c.goal_x == 4 && c.goal_y == 0) first_corner = i;
    if (!first_goal && c.goal_x == 4 && c.goal_y == 3) first_goal = i;
  }
  EXPECT_GT(first_corner, 0u);
  EXPECT_GT(first_goal, first_corner);
  // The robot drove along the L (about 7 m), not the 5 m diagonal.
  EXPECT_GT(h.robot.state.path_length, 6.5);
  EXPECT_TRUE(h.commands[first_corner].set_head) << "goto looks ahead";
}

// A goal beside an obstacle: the planner moves it to the nearest free cell
// and its path ends there. The robot stops there, the goto done, rather than
// driving the last stretch into the obstacle.
TEST(Executor, GotoToAGoalThePlannerMovedEndsAtThePathsEndWithoutTouching) {
  Harness h;
  h.robot.obstacles.push_back({4.0, 0.35, 0.3});  // the goal (4, 0) is 0.35 m from it: blocked
  h.planner = [](const beft::plan_request_t& r) {
    return answer(r, {{r.start_x, r.start_y, 0}, {2, -0.4, 0}, {3.5, -0.4, 0}});  // ends at the nearest free cell
  };
  const int64_t id = h.stack.push(gotoTask(4, 0, 0));
  h.run(200);
  ASSERT_TRUE(h.stack.empty());
  const TaskEvent* end = h.lastEventOf(id);
  ASSERT_NE(end, nullptr);
  EXPECT_EQ(end->kind, TaskEvent::Kind::Done) << end->reason;
  EXPECT_NE(end->reason.find("nearest the blocked goal"), std::string::npos) << end->reason;
  EXPECT_EQ(h.robot.state.collisions, 0);
  EXPECT_NEAR(h.robot.state.x, 3.5, 0.15);
  EXPECT_NEAR(h.robot.state.y, -0.4, 0.15);
  EXPECT_EQ(h.requests.size(), 1u);
}

TEST(Executor, GotoReplansAfterACollision) {
  Harness h;
  h.robot.obstacles.push_back({3, 0, 0.5});
  h.planner = [&](const beft::plan_request_t& r) {
    if (h.requests.size() == 1)  // first: straight through the unseen obstacle
      return answer(r, {{r.start_x, r.start_y, 0}, {6, 0, 0}});
    return answer(r, {{r.start_x, r.start_y, 90}, {r.start_x, 2, 0}, {6, 2, -90}, {6, 0, 0}});
  };
  const int64_t id = h.stack.push(gotoTask(6, 0, 0));
  h.run(300);
  ASSERT_TRUE(h.stack.empty());
  EXPECT_EQ(h.lastEventOf(id)->kind, TaskEvent::Kind::Done) << h.lastEventOf(id)->reason;
  ASSERT_EQ(h.requests.size(), 2u);
  EXPECT_NEAR(h.requests[1].start_x, 2.2 - 0.3, 0.15) << "backed off 0.3 m from the contact, then replanned";
  EXPECT_GE(h.robot.state.collisions, 1);
  EXPECT_NEAR(h.robot.state.x, 6, 0.2);
  bool logged = false;
  for (const auto& line : h.log) logged |= line.find("collided") != std::string::npos;
  EXPECT_TRUE(logged);
}

TEST(Executor, GotoWithoutBackoffReplansWhereItStopped) {
  ExecutorParameters p;
  p.backoff_m = 0;
  Harness h(p);
  h.robot.obstacles.push_back({3, 0, 0.5});
  h.planner = [&](const beft::plan_request_t& r) {
    if (h.requests.size() == 1) return answer(r, {{r.start_x, r.start_y, 0}, {6, 0, 0}});
    return answer(r, {{r.start_x, r.start_y, 90}, {r.start_x, 2, 0}, {6, 2, -90}, {6, 0, 0}});
  };
  h.stack.push(gotoTask(6, 0, 0));
  h.run(300);
  ASSERT_EQ(h.requests.size(), 2u);
  EXPECT_NEAR(h.requests[1].start_x, 2.2, 0.15);
}

TEST(Executor, GotoGivesUpAfterRepeatedCollisions) {
  ExecutorParameters p;
  p.max_replans = 2;
  p.max_contacts_at_place = 100;  // the replan count decides here, not the place
  Harness h(p);
  h.robot.obstacles.push_back({3, 0, 0.5});
  h.planner = [](const beft::plan_request_t& r) { return answer(r, {{r.start_x, r.start_y, 0}, {6, 0, 0}}); };
  const int64_t id = h.stack.push(gotoTask(6, 0, 0));
  h.run(300);
  ASSERT_TRUE(h.stack.empty());
  EXPECT_EQ(h.lastEventOf(id)->kind, TaskEvent::Kind::Failed);
  EXPECT_NE(h.lastEventOf(id)->reason.find("collided"), std::string::npos) << h.lastEventOf(id)->reason;
  EXPECT_EQ(h.robot.state.collisions, 3);
}

// A planner that keeps sending the robot into the same obstacle: the second
// contact at that place ends the goto as blocked (the explorer then picks
// another target), and the robot backed off along ground it had driven.
TEST(Executor, GotoFailsAsBlockedAtTheSecondContactAtOnePlace) {
  Harness h;
  h.robot.obstacles.push_back({3, 0, 0.5});
  h.planner = [](const beft::plan_request_t& r) { return answer(r, {{r.start_x, r.start_y, 0}, {6, 0, 0}}); };
  const int64_t id = h.stack.push(gotoTask(6, 0, 0));
  h.run(300);
  ASSERT_TRUE(h.stack.empty());
  EXPECT_EQ(h.lastEventOf(id)->kind, TaskEvent::Kind::Failed);
  EXPECT_NE(h.lastEventOf(id)->reason.find("blocked: 2 contacts"), std::string::npos) << h.lastEventOf(id)->reason;
  EXPECT_EQ(h.robot.state.collisions, 2);
  // Every position the robot held lies on its straight way in (y = 0), behind the contact.
  EXPECT_LT(h.robot.state.x, 2.3);
  EXPECT_NEAR(h.robot.state.y, 0.0, 1e-9);
}

// goto turns the head to where the robot drives and drives only while the
// camera looks within look_before_moving_deg of that way: it never moves into
// ground it could not see.
TEST(Executor, GotoLooksAlongThePathAndDrivesOnlyWhileItSeesTheWay) {
  ExecutorParameters p;
  Harness h(p);
  h.planner = [](const beft::plan_request_t& r) {
    return answer(r, {{r.start_x, r.start_y, 90}, {0, 3, 90}, {-3, 3, 180}});
  };
  const int64_t id = h.stack.push(gotoTask(-3, 3, 180));
  int moves = 0, looks_ahead = 0;
  for (int i = 0; i < 200 && !h.stack.empty(); ++i) {
    const beft::robot_state_t before = h.robot.state;
    h.step();
    const beft::robot_command_t& command = h.commands.back();
    const bool moved = std::hypot(h.robot.state.x - before.x, h.robot.state.y - before.y) > 1e-9;
    if (!moved) continue;
    ++moves;
    const double way = std::atan2(h.robot.state.y - before.y, h.robot.state.x - before.x) * 180 / kPi;
    const double camera = before.yaw + before.head_yaw;
    EXPECT_LE(std::abs(model::wrapDegrees(way - camera)), p.look_before_moving_deg + 1e-6)
        << "moved towards " << way << " deg while the camera looked at " << camera << " deg (tick " << i << ")";
    if (command.set_head) ++looks_ahead;
  }
  ASSERT_TRUE(h.stack.empty());
  EXPECT_EQ(h.lastEventOf(id)->kind, TaskEvent::Kind::Done);
  EXPECT_GT(moves, 40);
  EXPECT_GT(looks_ahead, moves / 2);
}

// A free 10 x 4 m map, x in [0, 10], y in [-2, 2], at 0.1 m: row 20 holds y = 0.
planners::ObstacleCells freeMap() {
  planners::ObstacleCells map;
  map.width = 100;
  map.height = 40;
  map.resolution = 0.1;
  map.origin_x = 0;
  map.origin_y = -2;
  map.cells.assign(static_cast<size_t>(map.width * map.height), beft::obstacle_map_t::CELL_FREE);
  return map;
}

TEST(Executor, GotoReplansWhenANewlyMappedObstacleBlocksThePath) {
  ExecutorParameters p;
  p.max_replans = 0;  // map changes are not failures: they do not count
  Harness h(p);
  h.planner = [&](const beft::plan_request_t& r) {
    if (h.requests.size() == 1) return answer(r, {{r.start_x, r.start_y, 0}, {8, 0, 0}});
    return answer(r, {{r.start_x, r.start_y, 90}, {r.start_x, 2, 0}, {8, 2, -90}, {8, 0, 0}});
  };
  h.stack.push(gotoTask(8, 0, 0));
  h.run(5);
  EXPECT_EQ(h.requests.size(), 1u);
  // A wall appears on the map across the path at x = 5.
  planners::ObstacleCells map = freeMap();
  for (int y = 10; y < 30; ++y) map.cells[static_cast<size_t>(y * map.width + 50)] = beft::obstacle_map_t::CELL_OCCUPIED;
  h.executor.setObstacleMap(map);
  h.step();
  EXPECT_EQ(h.requests.size(), 2u);
  // The same map again is no change: no further replan.
  h.executor.setObstacleMap(map);
  h.run(3);
  EXPECT_EQ(h.requests.size(), 2u);
  h.run(300);
  EXPECT_TRUE(h.stack.empty());
  EXPECT_EQ(h.robot.state.collisions, 0);
}

// A path planned before a wall was seen that passes it closer than the
// robot's radius (with a margin) is replanned, not followed into contact; one
// that keeps clear of it is followed.
TEST(Executor, GotoReplansAPathThatGrazesANewlyMappedWall) {
  for (const int rows_away : {4, 5}) {  // the wall's cells from the path's, 0.1 m each: 0.4 m, 0.5 m
    SCOPED_TRACE(rows_away);
    Harness h;
    h.robot.state.radius = 0.35;  // the margin 0.1 m: 0.45 m kept clear
    h.planner = [&](const beft::plan_request_t& r) { return answer(r, {{r.start_x, r.start_y, 0}, {8, 0, 0}}); };
    h.stack.push(gotoTask(8, 0, 0));
    h.run(5);
    ASSERT_EQ(h.requests.size(), 1u);
    // A wall along the path, rows_away cells beside it, from x = 4 to 6.
    planners::ObstacleCells map = freeMap();
    const int row = 20 + rows_away;  // row 20 holds y = 0, the path
    for (int x = 40; x < 60; ++x) map.cells[static_cast<size_t>(row * map.width + x)] = beft::obstacle_map_t::CELL_OCCUPIED;
    h.executor.setObstacleMap(map);
    h.step();
    EXPECT_EQ(h.requests.size(), rows_away == 4 ? 2u : 1u);
  }
}

TEST(Executor, GotoFailsCleanlyWithoutAPlanner) {
  Harness h;  // no planner: requests go unanswered
  const int64_t id = h.stack.push(gotoTask(5, 5, 0));
  h.run(20);
  ASSERT_TRUE(h.stack.empty());
  const TaskEvent* end = h.lastEventOf(id);
  ASSERT_NE(end, nullptr);
  EXPECT_EQ(end->kind, TaskEvent::Kind::Failed);
  EXPECT_NE(end->reason.find("no answer from the planner"), std::string::npos) << end->reason;
  EXPECT_EQ(static_cast<int>(h.requests.size()), ExecutorParameters{}.max_failed_plans);
  for (const auto& c : h.commands) EXPECT_EQ(c.mode, beft::robot_command_t::MODE_STOP);
  EXPECT_EQ(h.executor.awaitedRequest(), 0);
}

TEST(Executor, GotoFailsWithThePlannersReasonWhenThereIsNoPath) {
  ExecutorParameters p;
  p.max_failed_plans = 2;
  Harness h(p);
  h.planner = [](const beft::plan_request_t& r) { return answer(r, {}, false); };
  const int64_t id = h.stack.push(gotoTask(5, 5, 0));
  h.run(20);
  const TaskEvent* end = h.lastEventOf(id);
  ASSERT_NE(end, nullptr);
  EXPECT_EQ(end->kind, TaskEvent::Kind::Failed);
  EXPECT_NE(end->reason.find("inside an obstacle"), std::string::npos) << end->reason;
  EXPECT_EQ(h.requests.size(), 2u);
}

TEST(Executor, AnswersToOtherRequestsAreIgnored) {
  Harness h;
  h.planner = [](const beft::plan_request_t& r) {
    beft::plan_request_t other = r;
    other.request_id = r.request_id + 1000;
    return answer(other, {{0, 0, 0}, {1, 0, 0}});
  };
  h.stack.push(gotoTask(5, 0, 0));
  h.step();
  EXPECT_NE(h.executor.awaitedRequest(), 0);
  EXPECT_FALSE(h.executor.awaitedResultArrived());
}

TEST(Executor, GotoAlreadyThereIsDoneWithoutPlanning) {
  Harness h;
  h.stack.push(gotoTask(0.1, 0, NAN));
  h.step();
  EXPECT_TRUE(h.stack.empty());
  EXPECT_TRUE(h.requests.empty());
}

TEST(Executor, ReflexInterruptsAGotoWhichResumesWithoutReplanning) {
  Harness h;
  h.planner = [](const beft::plan_request_t& r) { return answer(r, {{r.start_x, r.start_y, 0}, {6, 0, 0}}); };
  const int64_t go = h.stack.push(gotoTask(6, 0, 0));
  h.run(10);
  const double x_before = h.robot.state.x;
  Task look;
  look.kind = kinds::kLookAt;
  look.object_id = "victim";
  look.priority = 100;
  look.origin = "dw";
  h.executor.setObjectPositions({{"victim", {x_before + 1, 3}}});  // ahead left, within the head's range
  const int64_t reflex = h.stack.push(look);
  h.step();
  EXPECT_EQ(h.commands.back().mode, beft::robot_command_t::MODE_HEAD_ONLY);
  EXPECT_TRUE(h.commands.back().set_head);
  EXPECT_NEAR(h.commands.back().head_yaw, std::atan2(3.0, 1.0) * 180 / kPi, 1e-9);
  h.run(100);
  ASSERT_NE(h.lastEventOf(reflex), nullptr);
  EXPECT_EQ(h.lastEventOf(reflex)->kind, TaskEvent::Kind::Done) << h.lastEventOf(reflex)->reason;
  EXPECT_EQ(h.lastEventOf(go)->kind, TaskEvent::Kind::Done);
  EXPECT_EQ(h.requests.size(), 1u) << "the robot did not move while it looked";
}

TEST(Executor, LookAtWithinTheHeadsRangeTurnsOnlyTheHead) {
  Harness h;
  h.executor.setObjectPositions({{"radio", {2, 2}}});  // 45 deg left
  Task look;
  look.kind = kinds::kLookAt;
  look.object_id = "radio";
  const int64_t id = h.stack.push(look);
  h.run(50);
  EXPECT_EQ(h.lastEventOf(id)->kind, TaskEvent::Kind::Done);
  EXPECT_NEAR(h.robot.state.head_yaw, 45, 3);
  EXPECT_NEAR(h.robot.state.yaw, 0, 1e-9);
}

TEST(Executor, LookAtBehindTurnsThePlatform) {
  Harness h;
  h.executor.setObjectPositions({{"fire", {-3, -0.5}}});  // behind, slightly right
  Task look;
  look.kind = kinds::kLookAt;
  look.object_id = "fire";
  const int64_t id = h.stack.push(look);
  h.step();
  EXPECT_EQ(h.commands.back().mode, beft::robot_command_t::MODE_GOTO);
  EXPECT_DOUBLE_EQ(h.commands.back().goal_x, 0);
  h.run(100);
  EXPECT_EQ(h.lastEventOf(id)->kind, TaskEvent::Kind::Done) << h.lastEventOf(id)->reason;
  const double bearing = bearingDeg(0, 0, -3, -0.5);
  EXPECT_NEAR(model::wrapDegrees(h.robot.state.yaw + h.robot.state.head_yaw - bearing), 0, 3);
  EXPECT_GT(std::abs(h.robot.state.yaw), 90);
  EXPECT_NEAR(h.robot.state.x, 0, 1e-9) << "turned in place";
}

TEST(Executor, LookAtTurnsThePlatformWhenTheHeadStopsShort) {
  Harness h;
  h.robot.head_limit = 40;  // narrower than the executor's 85 deg
  h.executor.setObjectPositions({{"radio", {1, 3}}});  // 71.6 deg left
  Task look;
  look.kind = kinds::kLookAt;
  look.object_id = "radio";
  const int64_t id = h.stack.push(look);
  h.run(100);
  ASSERT_NE(h.lastEventOf(id), nullptr);
  EXPECT_EQ(h.lastEventOf(id)->kind, TaskEvent::Kind::Done) << h.lastEventOf(id)->reason;
  EXPECT_GT(h.robot.state.yaw, 25) << "the platform turned";
}

TEST(Executor, LookAtAnUnknownObjectFails) {
  Harness h;
  Task look;
  look.kind = kinds::kLookAt;
  look.object_id = "ghost";
  look.x = look.y = NAN;
  const int64_t id = h.stack.push(look);
  h.step();
  ASSERT_NE(h.lastEventOf(id), nullptr);
  EXPECT_EQ(h.lastEventOf(id)->kind, TaskEvent::Kind::Failed);
  EXPECT_NE(h.lastEventOf(id)->reason.find("ghost"), std::string::npos);
}

TEST(Executor, TurnHeadTurnAndWait) {
  Harness h;
  Task head;
  head.kind = kinds::kTurnHead;
  head.yaw = -30;
  Task turn;
  turn.kind = kinds::kTurn;
  turn.yaw = 120;
  Task wait;
  wait.kind = kinds::kWait;
  wait.x = 1.0;
  // Equal priority: each goes below the previous, so they run in push order.
  const int64_t a = h.stack.push(head), b = h.stack.push(turn), c = h.stack.push(wait);
  int ticks = 0;
  while (!h.stack.empty() && ticks < 200) {
    h.step();
    ++ticks;
  }
  EXPECT_EQ(h.lastEventOf(a)->kind, TaskEvent::Kind::Done);
  EXPECT_EQ(h.lastEventOf(b)->kind, TaskEvent::Kind::Done);
  EXPECT_EQ(h.lastEventOf(c)->kind, TaskEvent::Kind::Done);
  EXPECT_NEAR(h.robot.state.head_yaw, -30, 2);
  EXPECT_NEAR(h.robot.state.yaw, 120, 5);
  EXPECT_GE(ticks, 10 + 13) << "the wait lasted 1 s of simulated time after the turns";
}

TEST(Executor, TurnHeadBeyondTheRangeIsLimited) {
  Harness h;
  Task head;
  head.kind = kinds::kTurnHead;
  head.yaw = 150;
  const int64_t id = h.stack.push(head);
  h.run(50);
  EXPECT_EQ(h.lastEventOf(id)->kind, TaskEvent::Kind::Done);
  EXPECT_NEAR(h.robot.state.head_yaw, 85, 2);
  EXPECT_NE(h.lastEventOf(id)->reason.find("range"), std::string::npos);
}

TEST(Executor, OwnedTaskHoldsWhileItsOwnerActsAndFailsWhenTheOwnerIsSilent) {
  ExecutorParameters p;
  p.owned_idle_s = 2;
  Harness h(p);
  Task verify;
  verify.kind = "verify";
  verify.origin = "explore";
  verify.priority = 20;
  const int64_t id = h.stack.push(verify);
  h.run(5);
  EXPECT_EQ(h.stack.top()->id, id);
  EXPECT_EQ(h.commands.back().mode, beft::robot_command_t::MODE_STOP);
  // The owner pushes a sub-task: it runs, then the owner has 2 s again.
  Task wait;
  wait.kind = kinds::kWait;
  wait.x = 1.5;
  wait.parent = id;
  h.stack.push(wait);
  h.run(16);
  EXPECT_EQ(h.stack.top()->id, id) << "resumed after its sub-task";
  h.run(100);
  ASSERT_NE(h.lastEventOf(id), nullptr);
  EXPECT_EQ(h.lastEventOf(id)->kind, TaskEvent::Kind::Failed);
  EXPECT_NE(h.lastEventOf(id)->reason.find("explore"), std::string::npos);
  EXPECT_GE(h.utime, (5 + 16 + 20) * kTickUs);
}

TEST(Executor, AnEmptyStackStopsTheRobot) {
  Harness h;
  h.step();
  EXPECT_EQ(h.commands.back().mode, beft::robot_command_t::MODE_STOP);
  EXPECT_FALSE(h.commands.back().set_head);
  EXPECT_EQ(h.commands.back().source, "tasks");
}

}  // namespace
}  // namespace beft::tasks
