// The one way TASK_COMMAND messages are made (lib/task/task_commands.hpp).
#include <gtest/gtest.h>

#include <vector>

#include "lib/task/task_commands.hpp"
#include "lib/task/task_messages.hpp"

using beft::task_command_t;
using beft::task_t;
namespace tasks = beft::tasks;

namespace {

std::vector<uint8_t> encoded(const task_command_t& command) {
  std::vector<uint8_t> bytes(static_cast<std::size_t>(command.getEncodedSize()));
  command.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

}  // namespace

TEST(TaskCommands, APushCarriesEveryFieldOfTheTaskAndTheSendersNumbers) {
  tasks::Task look;
  look.parent = 7;
  look.kind = tasks::kinds::kLookAt;
  look.priority = 90;
  look.x = 1.5;
  look.y = -2.25;
  look.yaw = 30;
  look.object_id = "radio1";
  look.origin = "dw";
  look.note = "turn-to reflex";
  const task_command_t command = tasks::pushCommand(look, 4'000'000, 12);
  EXPECT_EQ(command.command, task_command_t::COMMAND_PUSH);
  EXPECT_EQ(command.utime, 4'000'000);
  EXPECT_EQ(command.command_id, 12);
  EXPECT_EQ(command.task.task_id, 0);  // the stack assigns it
  const tasks::Task back = tasks::fromMessage(command.task);
  EXPECT_EQ(back.parent, 7);
  EXPECT_EQ(back.kind, "look_at");
  EXPECT_EQ(back.priority, 90);
  EXPECT_DOUBLE_EQ(back.x, 1.5);
  EXPECT_DOUBLE_EQ(back.y, -2.25);
  EXPECT_DOUBLE_EQ(back.yaw, 30);
  EXPECT_EQ(back.object_id, "radio1");
  EXPECT_EQ(back.origin, "dw");
  EXPECT_EQ(back.note, "turn-to reflex");
  EXPECT_EQ(back.status, tasks::Status::Pending);
}

TEST(TaskCommands, APopNamesTheTaskItsOutcomeAndReasonAndNothingElse) {
  const task_command_t done = tasks::popCommand(41, tasks::Status::Done, "seen", "exploration", 5, 3);
  EXPECT_EQ(done.command, task_command_t::COMMAND_POP);
  EXPECT_EQ(done.task.task_id, 41);
  EXPECT_EQ(done.task.status, task_t::STATUS_DONE);
  EXPECT_EQ(done.task.note, "seen");
  EXPECT_EQ(done.task.origin, "exploration");
  EXPECT_EQ(done.task.kind, "");
  EXPECT_EQ(done.task.priority, 0);
  EXPECT_EQ(tasks::popCommand(41, tasks::Status::Failed, "", "user", 5, 3).task.status, task_t::STATUS_FAILED);
  EXPECT_EQ(tasks::popCommand(0, tasks::Status::Pending, "", "user", 5, 3).task.status, task_t::STATUS_PENDING);
}

TEST(TaskCommands, AClearIsAnEmptyTaskOnBehalfOfItsOrigin) {
  const task_command_t clear = tasks::clearCommand("user", 9, 2);
  EXPECT_EQ(clear.command, task_command_t::COMMAND_CLEAR);
  EXPECT_EQ(clear.utime, 9);
  EXPECT_EQ(clear.command_id, 2);
  EXPECT_EQ(clear.task.origin, "user");
  EXPECT_EQ(clear.task.task_id, 0);
}

TEST(TaskCommands, TheSameCommandEncodesToTheSameBytes) {
  // Commands travel on a data-plane channel: a field left unset would make
  // two runs differ.
  tasks::Task turn;
  turn.kind = tasks::kinds::kTurnHead;
  turn.yaw = -45;
  EXPECT_EQ(encoded(tasks::pushCommand(turn, 1, 1)), encoded(tasks::pushCommand(turn, 1, 1)));
  EXPECT_EQ(encoded(tasks::popCommand(3, tasks::Status::Done, "r", "o", 1, 1)),
            encoded(tasks::popCommand(3, tasks::Status::Done, "r", "o", 1, 1)));
}
