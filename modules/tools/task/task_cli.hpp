// The logic of beft-task: turning "push KIND ARGS..." into a task, and a task
// stack message into readable text. No LCM here.
#pragma once

#include <string>
#include <vector>

#include <beft/task_stack_t.hpp>

#include "lib/task/task.hpp"

namespace beft::task_cli {

// The task that "push KIND ARGS..." describes:
//   goto X Y [YAW]       (no YAW: any final heading)
//   turn_head YAW | turn YAW
//   look_at OBJECT | look_at X Y
//   wait SECONDS
//   any other kind: [OBJECT] [X Y [YAW]]   (composite tasks owned by an expert)
// Throws std::invalid_argument saying which argument is wrong and the usage.
tasks::Task parsePush(const std::string& kind, const std::vector<std::string>& args);

// A number, or std::invalid_argument naming what it was meant to be.
double parseNumber(const std::string& text, const std::string& what);

// The usage lines of push, one per kind.
std::string pushUsage();

// The stack as an aligned table, top first, with the simulated time.
std::string formatStack(const beft::task_stack_t& stack);
// The stack as JSON (an object with utime, tick and tasks).
std::string stackJson(const beft::task_stack_t& stack);

}  // namespace beft::task_cli
