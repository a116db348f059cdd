// Conversions between the task stack's plain types and its LCM messages
// (task_t, task_stack_t, task_events_t).
#pragma once

#include <cstdint>
#include <vector>

#include <beft/task_events_t.hpp>
#include <beft/task_stack_t.hpp>
#include <beft/task_t.hpp>

#include "lib/task/task_stack.hpp"

namespace beft::tasks {

beft::task_t toMessage(const Task& task);
Task fromMessage(const beft::task_t& message);  // an unknown status reads as Pending

beft::task_stack_t stackMessage(const TaskStack& stack, int64_t utime, int64_t tick);
beft::task_events_t eventsMessage(const std::vector<TaskEvent>& events, int64_t utime, int64_t tick);

int8_t eventCode(TaskEvent::Kind kind);  // task_event_t::EVENT_*

}  // namespace beft::tasks
