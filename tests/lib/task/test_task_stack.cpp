// The task stack: priorities, interruption and resumption, sub-tasks, clear,
// and how a sub-task's end reaches its parent.
#include <gtest/gtest.h>

#include <cmath>

#include "lib/task/task_stack.hpp"

namespace beft::tasks {
namespace {

Task make(const std::string& kind, int priority, int64_t parent = 0) {
  Task t;
  t.kind = kind;
  t.priority = priority;
  t.parent = parent;
  t.x = 1;
  t.y = 2;
  t.yaw = 0;
  t.origin = "test";
  return t;
}

std::vector<int64_t> ids(const TaskStack& stack) {
  std::vector<int64_t> out;
  for (const auto& t : stack.tasks()) out.push_back(t.id);
  return out;
}

std::vector<TaskEvent::Kind> kindsOf(const std::vector<TaskEvent>& events, int64_t id) {
  std::vector<TaskEvent::Kind> out;
  for (const auto& e : events)
    if (e.task.id == id) out.push_back(e.kind);
  return out;
}

using K = TaskEvent::Kind;

TEST(TaskStack, FirstTaskStartsAndIdsIncrease) {
  TaskStack stack;
  const int64_t a = stack.push(make("goto", 10), 77);
  const int64_t b = stack.push(make("wait", 10));
  EXPECT_EQ(a, 1);
  EXPECT_EQ(b, 2);
  ASSERT_NE(stack.top(), nullptr);
  EXPECT_EQ(stack.top()->id, a);
  EXPECT_EQ(stack.top()->status, Status::Active);
  EXPECT_EQ(stack.find(b)->status, Status::Pending);
  const auto events = stack.takeEvents();
  ASSERT_GE(events.size(), 2u);
  EXPECT_EQ(events[0].kind, K::Pushed);
  EXPECT_EQ(events[0].command_id, 77);
  EXPECT_EQ(events[1].kind, K::Started);
  EXPECT_TRUE(stack.takeEvents().empty());
}

TEST(TaskStack, HigherPriorityInterruptsAndTheTopResumesAfterwards) {
  TaskStack stack;
  const int64_t goal = stack.push(make("goto", 10));
  const int64_t reflex = stack.push(make("look_at", 100));
  EXPECT_EQ(ids(stack), (std::vector<int64_t>{reflex, goal}));
  EXPECT_EQ(stack.find(goal)->status, Status::Suspended);
  EXPECT_EQ(stack.find(reflex)->status, Status::Active);
  stack.takeEvents();

  ASSERT_TRUE(stack.finish(reflex, Status::Done, "facing it"));
  EXPECT_EQ(ids(stack), (std::vector<int64_t>{goal}));
  EXPECT_EQ(stack.top()->status, Status::Active);
  const auto events = stack.takeEvents();
  EXPECT_EQ(kindsOf(events, reflex), (std::vector<K>{K::Done}));
  EXPECT_EQ(kindsOf(events, goal), (std::vector<K>{K::Resumed}));
  EXPECT_EQ(events[0].task.status, Status::Done);
  EXPECT_EQ(events[0].reason, "facing it");
}

TEST(TaskStack, EqualOrLowerPriorityGoesBelowTheHigherOnes) {
  TaskStack stack;
  const int64_t a = stack.push(make("goto", 50));
  const int64_t b = stack.push(make("goto", 50));  // equal: below a
  const int64_t c = stack.push(make("goto", 10));  // lower: at the bottom
  const int64_t d = stack.push(make("goto", 30));  // between
  const int64_t e = stack.push(make("goto", 60));  // higher than all: top
  EXPECT_EQ(ids(stack), (std::vector<int64_t>{e, a, b, d, c}));
  EXPECT_EQ(stack.find(a)->status, Status::Suspended);  // it had started
  EXPECT_EQ(stack.find(b)->status, Status::Pending);    // it never ran
}

TEST(TaskStack, SubTasksGoAboveTheirParentAndRunInTheOrderPushed) {
  TaskStack stack;
  const int64_t other = stack.push(make("goto", 5));
  const int64_t verify = stack.push(make("verify", 20));
  const int64_t go = stack.push(make("goto", 0, verify));
  const int64_t look = stack.push(make("look_at", 0, verify));
  EXPECT_EQ(ids(stack), (std::vector<int64_t>{go, look, verify, other}));
  EXPECT_EQ(stack.find(go)->priority, 20) << "a sub-task runs at least at its parent's priority";
  EXPECT_EQ(stack.find(verify)->status, Status::Suspended);
  EXPECT_TRUE(stack.hasSubTasks(verify));
  EXPECT_TRUE(stack.isDescendant(look, verify));
  EXPECT_FALSE(stack.isDescendant(other, verify));

  // A grandchild goes directly above its parent; the reflex stays on top.
  const int64_t reflex = stack.push(make("look_at", 100));
  const int64_t grandchild = stack.push(make("turn_head", 0, go));
  EXPECT_EQ(ids(stack), (std::vector<int64_t>{reflex, grandchild, go, look, verify, other}));
  // An urgent sub-task goes above its lower-priority siblings, not above the reflex.
  const int64_t urgent = stack.push(make("turn", 50, verify));
  EXPECT_EQ(ids(stack), (std::vector<int64_t>{reflex, urgent, grandchild, go, look, verify, other}));
}

TEST(TaskStack, DoneSubTasksLetTheParentResume) {
  TaskStack stack;
  const int64_t verify = stack.push(make("verify", 20));
  const int64_t go = stack.push(make("goto", 0, verify));
  stack.takeEvents();
  stack.finish(go, Status::Done, "reached");
  EXPECT_EQ(ids(stack), (std::vector<int64_t>{verify}));
  EXPECT_EQ(stack.top()->status, Status::Active);
  EXPECT_EQ(kindsOf(stack.takeEvents(), verify), (std::vector<K>{K::Resumed}));
}

TEST(TaskStack, AFailedSubTaskFailsItsParentsUpTheChain) {
  TaskStack stack;
  const int64_t bottom = stack.push(make("goto", 1));
  const int64_t find_all = stack.push(make("find_all", 10));
  const int64_t verify = stack.push(make("verify", 10, find_all));
  const int64_t go = stack.push(make("goto", 10, verify));
  const int64_t sibling = stack.push(make("look_at", 10, find_all));
  stack.takeEvents();
  stack.finish(go, Status::Failed, "no path");
  EXPECT_EQ(ids(stack), (std::vector<int64_t>{bottom}));
  const auto events = stack.takeEvents();
  EXPECT_EQ(kindsOf(events, go), (std::vector<K>{K::Failed}));
  EXPECT_EQ(kindsOf(events, verify), (std::vector<K>{K::Failed}));
  EXPECT_EQ(kindsOf(events, find_all), (std::vector<K>{K::Failed}));
  EXPECT_EQ(kindsOf(events, sibling), (std::vector<K>{K::Removed}));
  for (const auto& e : events)
    if (e.task.id == verify) {
      EXPECT_NE(e.reason.find("no path"), std::string::npos) << e.reason;
      EXPECT_NE(e.reason.find("sub-task " + std::to_string(go)), std::string::npos) << e.reason;
      EXPECT_EQ(e.task.status, Status::Failed);
    }
  EXPECT_EQ(stack.top()->status, Status::Active);
}

TEST(TaskStack, OwnersCanHandleFailuresThemselves) {
  StackOptions options;
  options.child_failure_fails_parent = false;
  TaskStack stack(options);
  const int64_t verify = stack.push(make("verify", 10));
  const int64_t go = stack.push(make("goto", 10, verify));
  stack.finish(go, Status::Failed, "no path");
  EXPECT_EQ(ids(stack), (std::vector<int64_t>{verify}));
  EXPECT_EQ(stack.top()->status, Status::Active);
}

TEST(TaskStack, FinishingAParentRemovesItsSubTasks) {
  TaskStack stack;
  const int64_t verify = stack.push(make("verify", 10));
  const int64_t go = stack.push(make("goto", 10, verify));
  stack.takeEvents();
  EXPECT_TRUE(stack.finish(verify, Status::Done, "seen"));
  EXPECT_TRUE(stack.empty());
  const auto events = stack.takeEvents();
  EXPECT_EQ(kindsOf(events, go), (std::vector<K>{K::Removed}));
  EXPECT_EQ(kindsOf(events, verify), (std::vector<K>{K::Done}));
  EXPECT_FALSE(stack.finish(verify, Status::Done, ""));
}

TEST(TaskStack, PopCancelsTheTopAndClearEmptiesTheStack) {
  TaskStack stack;
  const int64_t a = stack.push(make("goto", 10));
  const int64_t b = stack.push(make("turn", 20));
  stack.takeEvents();
  EXPECT_TRUE(stack.pop(5));
  EXPECT_EQ(ids(stack), (std::vector<int64_t>{a}));
  auto events = stack.takeEvents();
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events[0].kind, K::Removed);
  EXPECT_EQ(events[0].task.id, b);
  EXPECT_EQ(events[0].command_id, 5);
  stack.push(make("wait", 3));
  stack.clear(6);
  EXPECT_TRUE(stack.empty());
  EXPECT_EQ(stack.top(), nullptr);
  events = stack.takeEvents();
  EXPECT_EQ(events.back().kind, K::Removed);
  EXPECT_EQ(events.back().reason, "cleared");
  EXPECT_FALSE(stack.pop());
}

TEST(TaskStack, RejectsBadTasksWithAReason) {
  TaskStack stack;
  Task bad = make("goto", 1);
  bad.x = NAN;
  EXPECT_EQ(stack.push(bad, 9), 0);
  EXPECT_EQ(stack.push(make("", 1)), 0);
  EXPECT_EQ(stack.push(make("goto", 1, 42)), 0);  // unknown parent
  Task wait = make("wait", 1);
  wait.x = -1;
  EXPECT_EQ(stack.push(wait), 0);
  Task look = make("look_at", 1);
  look.x = look.y = NAN;
  EXPECT_EQ(stack.push(look), 0);
  look.object_id = "victim";
  EXPECT_NE(stack.push(look), 0);
  const auto events = stack.takeEvents();
  ASSERT_GE(events.size(), 5u);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(events[i].kind, K::Rejected);
    EXPECT_FALSE(events[i].reason.empty());
  }
  EXPECT_EQ(events[0].command_id, 9);
  EXPECT_NE(events[2].reason.find("42"), std::string::npos);
  EXPECT_EQ(stack.tasks().size(), 1u);
}

TEST(TaskStack, RefusesPushesBeyondItsCapacity) {
  StackOptions options;
  options.max_tasks = 3;
  TaskStack stack(options);
  for (int i = 0; i < 3; ++i) EXPECT_NE(stack.push(make("wait", 1)), 0);
  EXPECT_EQ(stack.push(make("wait", 1)), 0);
  EXPECT_EQ(stack.tasks().size(), 3u);
}

TEST(TaskStack, DescribeNamesTheKindAndItsArguments) {
  Task t = make("goto", 1);
  t.x = 12;
  t.y = 8;
  t.yaw = 90;
  EXPECT_EQ(describe(t), "goto(12, 8, 90)");
  t.yaw = NAN;
  EXPECT_EQ(describe(t), "goto(12, 8, any)");
  Task look = make("look_at", 1);
  look.object_id = "victim1";
  EXPECT_EQ(describe(look), "look_at(victim1)");
  EXPECT_TRUE(isBuiltInKind("turn_head"));
  EXPECT_FALSE(isBuiltInKind("verify"));
}

}  // namespace
}  // namespace beft::tasks
