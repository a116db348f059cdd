// The task-stack expert class without LCM: commands apply at the next firing
// by origin, then in arrival order, a plan request holds the next firing until its answer
// (inputsReady), and what it publishes every firing.
#include <gtest/gtest.h>

#include <cmath>

#include <beft/plan_request_t.hpp>
#include <beft/plan_result_t.hpp>
#include <beft/robot_command_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/task_command_t.hpp>
#include <beft/task_events_t.hpp>
#include <beft/task_stack_t.hpp>

#include "lib/common/channels.hpp"
#include "tests/experts/support/expert_harness.hpp"
#include "lib/task/task_messages.hpp"
#include "experts/tasks/tasks_expert.hpp"

namespace beft::tasks {
namespace {

using testing_support::CollectingOutput;
using testing_support::deliver;
using testing_support::firing;

class TasksExpertTest : public ::testing::Test {
 protected:
  void SetUp() override { expert_.startUp(); }

  void robotAt(int64_t tick, double x, double y) {
    robot_state_t s{};
    s.utime = tick * 100000;
    s.tick = tick;
    s.x = x;
    s.y = y;
    s.yaw = 0;
    s.radius = 0.35;
    ASSERT_TRUE(deliver(expert_, channels::kRobotState, s));
  }
  void push(int64_t command_id, const std::string& kind, double x, double y, int priority,
            const std::string& object = "", const std::string& origin = "test") {
    Task t;
    t.kind = kind;
    t.x = x;
    t.y = y;
    t.yaw = NAN;
    t.priority = priority;
    t.object_id = object;
    t.origin = origin;
    task_command_t c{};
    c.utime = 0;
    c.command_id = command_id;
    c.command = task_command_t::COMMAND_PUSH;
    c.task = toMessage(t);
    ASSERT_TRUE(deliver(expert_, channels::kTaskCommand, c));
  }
  void fire(int64_t tick) { ASSERT_TRUE(expert_.fire(firing("tasks", tick), out_).ok); }

  TasksExpert expert_;
  CollectingOutput out_;
};

TEST_F(TasksExpertTest, AppliesCommandsAtTheNextFiringInArrivalOrder) {
  push(11, "wait", 5, 0, 10);
  push(12, "wait", 7, 0, 10);
  robotAt(0, 1, 1);
  EXPECT_TRUE(out_.published.empty()) << "onMessage only stores";
  fire(0);
  const auto stacks = out_.on<task_stack_t>(channels::kTaskStack);
  ASSERT_EQ(stacks.size(), 1u);
  ASSERT_EQ(stacks[0].num_tasks, 2);
  EXPECT_EQ(stacks[0].tasks[0].task_id, 1);
  EXPECT_DOUBLE_EQ(stacks[0].tasks[0].x, 5) << "the first pushed runs first";
  EXPECT_EQ(stacks[0].tasks[0].status, task_t::STATUS_ACTIVE);
  EXPECT_EQ(stacks[0].tasks[1].note, "wait(7 s)");
  const auto events = out_.on<task_events_t>(channels::kTaskEvents);
  ASSERT_EQ(events.size(), 1u);
  ASSERT_GE(events[0].num_events, 2);
  EXPECT_EQ(events[0].events[0].event, task_event_t::EVENT_PUSHED);
  EXPECT_EQ(events[0].events[0].command_id, 11);
  const auto commands = out_.on<robot_command_t>(channels::kRobotCommand);
  ASSERT_EQ(commands.size(), 1u);
  EXPECT_EQ(commands[0].mode, robot_command_t::MODE_STOP);
  EXPECT_EQ(commands[0].utime, 0);

  // Nothing changed next tick: no TASK_EVENTS, but TASK_STACK and ROBOT_CMD again.
  out_.clear();
  robotAt(1, 1, 1);
  fire(1);
  EXPECT_EQ(out_.on<task_stack_t>(channels::kTaskStack).size(), 1u);
  EXPECT_EQ(out_.on<robot_command_t>(channels::kRobotCommand).size(), 1u);
  EXPECT_TRUE(out_.on<task_events_t>(channels::kTaskEvents).empty());
}

// Two experts' commands of one tick reach the stack in the network's order;
// the stack orders them by origin, so a repaired (late) one changes nothing.
TEST_F(TasksExpertTest, CommandsOfDifferentOriginsApplyInOriginOrderWhateverTheirArrival) {
  push(5, "wait", 7, 0, 10, "", "dw");
  push(9, "wait", 5, 0, 10, "", "audio");
  push(6, "wait", 8, 0, 10, "", "dw");
  robotAt(0, 1, 1);
  fire(0);
  const auto stacks = out_.on<task_stack_t>(channels::kTaskStack);
  ASSERT_EQ(stacks.size(), 1u);
  ASSERT_EQ(stacks[0].num_tasks, 3);
  EXPECT_DOUBLE_EQ(stacks[0].tasks[0].x, 5) << "audio's push first, though it arrived second";
  EXPECT_EQ(stacks[0].tasks[0].origin, "audio");
  EXPECT_DOUBLE_EQ(stacks[0].tasks[1].x, 7) << "then dw's, in their arrival order";
  EXPECT_DOUBLE_EQ(stacks[0].tasks[2].x, 8);
}

TEST_F(TasksExpertTest, APlanRequestHoldsTheNextFiringUntilItsAnswer) {
  robotAt(0, 1, 1);
  push(1, "goto", 6, 1, 10);
  EXPECT_TRUE(expert_.inputsReady(firing("tasks", 0)));
  fire(0);
  const auto requests = out_.on<plan_request_t>(channels::kPlanRequest);
  ASSERT_EQ(requests.size(), 1u);
  EXPECT_DOUBLE_EQ(requests[0].start_x, 1);
  EXPECT_DOUBLE_EQ(requests[0].goal_x, 6);
  EXPECT_DOUBLE_EQ(requests[0].goal_yaw, 0) << "any heading: the direction of travel";

  robotAt(1, 1, 1);
  EXPECT_FALSE(expert_.inputsReady(firing("tasks", 1))) << "the answer has not come";
  plan_result_t other{};
  other.request_id = requests[0].request_id + 1;
  other.success = true;
  other.num_waypoints = 0;
  ASSERT_TRUE(deliver(expert_, channels::kPlanResult, other));
  EXPECT_FALSE(expert_.inputsReady(firing("tasks", 1))) << "an answer to someone else";
  plan_result_t answer{};
  answer.request_id = requests[0].request_id;
  answer.success = true;
  answer.planner = "test";
  for (double x : {1.0, 3.0, 6.0}) {
    waypoint_t w{};
    w.x = x;
    w.y = 1;
    w.yaw = 0;
    answer.waypoints.push_back(w);
  }
  answer.num_waypoints = 3;
  ASSERT_TRUE(deliver(expert_, channels::kPlanResult, answer));
  EXPECT_TRUE(expert_.inputsReady(firing("tasks", 1)));
  out_.clear();
  fire(1);
  const auto commands = out_.on<robot_command_t>(channels::kRobotCommand);
  ASSERT_EQ(commands.size(), 1u);
  EXPECT_EQ(commands[0].mode, robot_command_t::MODE_GOTO);
  EXPECT_DOUBLE_EQ(commands[0].goal_x, 3);
  EXPECT_TRUE(out_.on<plan_request_t>(channels::kPlanRequest).empty());
}

TEST_F(TasksExpertTest, LookAtFindsTheObjectInTheHypothesesOrTheAudio) {
  robotAt(0, 0, 0);
  acoustic_percepts_t audio{};
  audio.utime = 0;
  audio.tick = 0;
  acoustic_percept_t p{};
  p.object_id = "victim";
  p.est_x = 0;
  p.est_y = 5;  // straight left: 90 deg, beyond the head's 85
  audio.percepts.push_back(p);
  audio.num_percepts = 1;
  ASSERT_TRUE(deliver(expert_, channels::kAudio, audio));
  push(1, "look_at", NAN, NAN, 100, "victim");
  fire(0);
  const auto commands = out_.on<robot_command_t>(channels::kRobotCommand);
  ASSERT_EQ(commands.size(), 1u);
  EXPECT_EQ(commands[0].mode, robot_command_t::MODE_GOTO) << "the platform turns";
  EXPECT_DOUBLE_EQ(commands[0].goal_yaw, 90);
  EXPECT_TRUE(commands[0].set_head);
  EXPECT_DOUBLE_EQ(commands[0].head_yaw, 85);
}

TEST_F(TasksExpertTest, PopOfAnOwnedTaskAndClear) {
  robotAt(0, 0, 0);
  push(1, "verify", NAN, NAN, 20, "victim");
  fire(0);
  task_command_t finish{};
  finish.command_id = 2;
  finish.command = task_command_t::COMMAND_POP;
  finish.task = toMessage(Task{});
  finish.task.task_id = 1;
  finish.task.status = task_t::STATUS_FAILED;
  finish.task.note = "no viewpoint";
  ASSERT_TRUE(deliver(expert_, channels::kTaskCommand, finish));
  out_.clear();
  robotAt(1, 0, 0);
  fire(1);
  const auto events = out_.on<task_events_t>(channels::kTaskEvents);
  ASSERT_EQ(events.size(), 1u);
  ASSERT_EQ(events[0].num_events, 1);
  EXPECT_EQ(events[0].events[0].event, task_event_t::EVENT_FAILED);
  EXPECT_EQ(events[0].events[0].reason, "no viewpoint");
  EXPECT_EQ(events[0].events[0].command_id, 2);
  EXPECT_EQ(out_.on<task_stack_t>(channels::kTaskStack).back().num_tasks, 0);
}

TEST(TasksExpertParameters, RefusesBadValues) {
  TasksExpert expert;
  expert::Parameters p;
  p["goal_tolerance_m"] = "-1";
  EXPECT_THROW(expert.startUp(p), std::invalid_argument);
  p["goal_tolerance_m"] = "0.2";
  p["max_failed_plans"] = "0";
  EXPECT_THROW(expert.startUp(p), std::invalid_argument);
  p["max_failed_plans"] = "2";
  p["stall_s"] = "x";
  EXPECT_THROW(expert.startUp(p), std::invalid_argument);
  p["stall_s"] = "3";
  EXPECT_NO_THROW(expert.startUp(p));
}

}  // namespace
}  // namespace beft::tasks
