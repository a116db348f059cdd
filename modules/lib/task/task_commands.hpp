// Every TASK_COMMAND a process sends (the experts that push tasks, the
// explorer ending the tasks it owns, `beft task`), made one way, so that a
// command means the same whoever sends it.
#pragma once

#include <cstdint>
#include <string>

#include <beft/task_command_t.hpp>

#include "lib/task/task.hpp"

namespace beft::tasks {

// Push `task` (its id is left for the stack to assign).
beft::task_command_t pushCommand(const Task& task, int64_t utime, int64_t command_id);

// End the task `task_id` (0: the top task) with `outcome` (Done, Failed, or
// Pending for a plain pop) and the reason, on behalf of `origin`.
beft::task_command_t popCommand(int64_t task_id, Status outcome, const std::string& reason,
                                const std::string& origin, int64_t utime, int64_t command_id);

// Empty the stack, on behalf of `origin`.
beft::task_command_t clearCommand(const std::string& origin, int64_t utime, int64_t command_id);

}  // namespace beft::tasks
