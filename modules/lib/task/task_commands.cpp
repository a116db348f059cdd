#include "lib/task/task_commands.hpp"

#include "lib/task/task_messages.hpp"

namespace beft::tasks {
namespace {

beft::task_command_t command(int8_t kind, int64_t utime, int64_t command_id) {
  beft::task_command_t message{};
  message.utime = utime;
  message.command_id = command_id;
  message.command = kind;
  return message;
}

}  // namespace

beft::task_command_t pushCommand(const Task& task, int64_t utime, int64_t command_id) {
  beft::task_command_t message = command(beft::task_command_t::COMMAND_PUSH, utime, command_id);
  message.task = toMessage(task);
  return message;
}

beft::task_command_t popCommand(int64_t task_id, Status outcome, const std::string& reason,
                                const std::string& origin, int64_t utime, int64_t command_id) {
  beft::task_command_t message = command(beft::task_command_t::COMMAND_POP, utime, command_id);
  message.task.task_id = task_id;
  message.task.status = static_cast<int8_t>(outcome);
  message.task.note = reason;
  message.task.origin = origin;
  return message;
}

beft::task_command_t clearCommand(const std::string& origin, int64_t utime, int64_t command_id) {
  beft::task_command_t message = command(beft::task_command_t::COMMAND_CLEAR, utime, command_id);
  message.task.origin = origin;
  return message;
}

}  // namespace beft::tasks
