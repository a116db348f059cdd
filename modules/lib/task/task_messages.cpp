#include "lib/task/task_messages.hpp"

namespace beft::tasks {

beft::task_t toMessage(const Task& task) {
  beft::task_t m;
  m.task_id = task.id;
  m.parent_id = task.parent;
  m.kind = task.kind;
  m.priority = task.priority;
  m.x = task.x;
  m.y = task.y;
  m.yaw = task.yaw;
  m.object_id = task.object_id;
  m.status = static_cast<int8_t>(task.status);
  m.origin = task.origin;
  m.note = task.note;
  return m;
}

Task fromMessage(const beft::task_t& m) {
  Task task;
  task.id = m.task_id;
  task.parent = m.parent_id;
  task.kind = m.kind;
  task.priority = m.priority;
  task.x = m.x;
  task.y = m.y;
  task.yaw = m.yaw;
  task.object_id = m.object_id;
  task.status = m.status >= 0 && m.status <= static_cast<int8_t>(Status::Failed) ? static_cast<Status>(m.status)
                                                                               : Status::Pending;
  task.origin = m.origin;
  task.note = m.note;
  return task;
}

beft::task_stack_t stackMessage(const TaskStack& stack, int64_t utime, int64_t tick) {
  beft::task_stack_t m{};
  m.utime = utime;
  m.tick = tick;
  for (const auto& task : stack.tasks()) m.tasks.push_back(toMessage(task));
  m.num_tasks = static_cast<int32_t>(m.tasks.size());
  return m;
}

int8_t eventCode(TaskEvent::Kind kind) {
  using E = beft::task_event_t;
  switch (kind) {
    case TaskEvent::Kind::Pushed: return E::EVENT_PUSHED;
    case TaskEvent::Kind::Rejected: return E::EVENT_REJECTED;
    case TaskEvent::Kind::Started: return E::EVENT_STARTED;
    case TaskEvent::Kind::Suspended: return E::EVENT_SUSPENDED;
    case TaskEvent::Kind::Resumed: return E::EVENT_RESUMED;
    case TaskEvent::Kind::Done: return E::EVENT_DONE;
    case TaskEvent::Kind::Failed: return E::EVENT_FAILED;
    case TaskEvent::Kind::Removed: return E::EVENT_REMOVED;
  }
  return E::EVENT_REMOVED;
}

beft::task_events_t eventsMessage(const std::vector<TaskEvent>& events, int64_t utime, int64_t tick) {
  beft::task_events_t m{};
  m.utime = utime;
  m.tick = tick;
  for (const auto& event : events) {
    beft::task_event_t e;
    e.utime = utime;
    e.command_id = event.command_id;
    e.event = eventCode(event.kind);
    e.task = toMessage(event.task);
    e.reason = event.reason;
    m.events.push_back(e);
  }
  m.num_events = static_cast<int32_t>(m.events.size());
  return m;
}

}  // namespace beft::tasks
