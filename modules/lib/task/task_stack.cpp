#include "lib/task/task_stack.hpp"

#include <algorithm>
#include <cmath>

namespace beft::tasks {

const char* eventName(TaskEvent::Kind kind) {
  switch (kind) {
    case TaskEvent::Kind::Pushed: return "pushed";
    case TaskEvent::Kind::Rejected: return "rejected";
    case TaskEvent::Kind::Started: return "started";
    case TaskEvent::Kind::Suspended: return "suspended";
    case TaskEvent::Kind::Resumed: return "resumed";
    case TaskEvent::Kind::Done: return "done";
    case TaskEvent::Kind::Failed: return "failed";
    case TaskEvent::Kind::Removed: return "removed";
  }
  return "?";
}

std::string describeEvent(const TaskEvent& event) {
  const std::string what = event.task.kind.empty() ? std::string("command") : describe(event.task);
  return std::string(eventName(event.kind)) + " " +
         (event.task.id ? std::to_string(event.task.id) + " " : std::string()) + what + " from " +
         (event.task.origin.empty() ? "?" : event.task.origin) +
         (event.command_id ? " (command " + std::to_string(event.command_id) + ")" : "") +
         (event.reason.empty() ? "" : ": " + event.reason);
}

std::string validateTask(const Task& task) {
  if (task.kind.empty()) return "task has no kind";
  const auto finite = [](double v) { return std::isfinite(v); };
  if (task.kind == kinds::kGoto) {
    if (!finite(task.x) || !finite(task.y)) return "goto needs a finite x and y";
    if (std::isinf(task.yaw)) return "goto yaw must be finite (or NaN for any heading)";
  } else if (task.kind == kinds::kTurnHead || task.kind == kinds::kTurn) {
    if (!finite(task.yaw)) return task.kind + " needs a finite yaw";
  } else if (task.kind == kinds::kWait) {
    if (!finite(task.x) || task.x < 0) return "wait needs a duration x >= 0 s";
  } else if (task.kind == kinds::kLookAt) {
    if (task.object_id.empty() && (!finite(task.x) || !finite(task.y)))
      return "look_at needs an object id or a finite x and y";
  }
  return {};
}

int TaskStack::indexOf(int64_t id) const {
  for (std::size_t i = 0; i < tasks_.size(); ++i)
    if (tasks_[i].id == id) return static_cast<int>(i);
  return -1;
}

const Task* TaskStack::find(int64_t id) const {
  const int i = indexOf(id);
  return i < 0 ? nullptr : &tasks_[i];
}

bool TaskStack::isDescendant(int64_t id, int64_t ancestor) const {
  // Parents are always on the stack (a task leaves with its sub-tasks), and
  // the chain ends at 0; the bound guards against a malformed chain.
  const Task* task = find(id);
  for (std::size_t hops = 0; task != nullptr && hops <= tasks_.size(); ++hops) {
    if (task->parent == ancestor) return true;
    task = task->parent == 0 ? nullptr : find(task->parent);
  }
  return false;
}

bool TaskStack::hasSubTasks(int64_t id) const {
  return std::any_of(tasks_.begin(), tasks_.end(), [&](const Task& t) { return t.parent == id; });
}

void TaskStack::emit(TaskEvent::Kind kind, const Task& task, int64_t command_id, std::string reason) {
  events_.push_back(TaskEvent{kind, task, command_id, std::move(reason)});
}

std::vector<TaskEvent> TaskStack::takeEvents() {
  std::vector<TaskEvent> events;
  events.swap(events_);
  return events;
}

int64_t TaskStack::push(Task task, int64_t command_id) {
  task.id = 0;
  task.status = Status::Pending;
  std::string error = validateTask(task);
  int parent_index = -1;
  if (error.empty() && task.parent != 0) {
    parent_index = indexOf(task.parent);
    if (parent_index < 0) error = "parent task " + std::to_string(task.parent) + " is not on the stack";
  }
  if (error.empty() && tasks_.size() >= options_.max_tasks)
    error = "the stack is full (" + std::to_string(options_.max_tasks) + " tasks)";
  if (!error.empty()) {
    emit(TaskEvent::Kind::Rejected, task, command_id, error);
    return 0;
  }

  task.id = next_id_++;
  std::size_t position;
  if (parent_index >= 0) {
    // Directly above the parent, below its earlier sub-tasks of higher or
    // equal priority: siblings run in the order they were pushed.
    task.priority = std::max(task.priority, tasks_[parent_index].priority);
    int above = parent_index;
    while (above > 0 && isDescendant(tasks_[above - 1].id, task.parent) &&
           tasks_[above - 1].priority < task.priority)
      --above;
    position = static_cast<std::size_t>(above);
  } else {
    // Below every task of higher or equal priority.
    position = 0;
    while (position < tasks_.size() && tasks_[position].priority >= task.priority) ++position;
  }
  tasks_.insert(tasks_.begin() + static_cast<std::ptrdiff_t>(position), task);
  emit(TaskEvent::Kind::Pushed, task, command_id);
  updateStatuses(command_id);
  return task.id;
}

void TaskStack::removeSubTasks(int64_t id, const std::string& reason, int64_t command_id) {
  // Top first, so the deepest sub-tasks go first.
  for (std::size_t i = 0; i < tasks_.size();) {
    if (isDescendant(tasks_[i].id, id)) {
      Task removed = tasks_[i];
      tasks_.erase(tasks_.begin() + static_cast<std::ptrdiff_t>(i));
      emit(TaskEvent::Kind::Removed, removed, command_id, reason);
    } else {
      ++i;
    }
  }
}

bool TaskStack::finish(int64_t id, Status outcome, const std::string& reason, int64_t command_id) {
  if (outcome != Status::Done && outcome != Status::Failed) outcome = Status::Done;
  if (indexOf(id) < 0) return false;
  const std::string what = describe(*find(id));
  removeSubTasks(id, "parent " + std::to_string(id) + " ended", command_id);
  const int index = indexOf(id);
  Task ended = tasks_[index];
  tasks_.erase(tasks_.begin() + index);
  ended.status = outcome;
  if (!reason.empty()) ended.note = reason;
  emit(outcome == Status::Done ? TaskEvent::Kind::Done : TaskEvent::Kind::Failed, ended, command_id, reason);
  if (outcome == Status::Failed && options_.child_failure_fails_parent && ended.parent != 0 &&
      indexOf(ended.parent) >= 0) {
    finish(ended.parent, Status::Failed,
           "sub-task " + std::to_string(id) + " " + what + " failed" + (reason.empty() ? "" : ": " + reason),
           command_id);
    return true;  // the recursive call updated the statuses
  }
  updateStatuses(command_id);
  return true;
}

bool TaskStack::remove(int64_t id, const std::string& reason, int64_t command_id) {
  if (indexOf(id) < 0) return false;
  removeSubTasks(id, reason, command_id);
  const int index = indexOf(id);
  Task removed = tasks_[index];
  tasks_.erase(tasks_.begin() + index);
  emit(TaskEvent::Kind::Removed, removed, command_id, reason);
  updateStatuses(command_id);
  return true;
}

bool TaskStack::pop(int64_t command_id) {
  if (tasks_.empty()) return false;
  return remove(tasks_.front().id, "popped", command_id);
}

void TaskStack::clear(int64_t command_id) {
  for (const auto& task : tasks_) emit(TaskEvent::Kind::Removed, task, command_id, "cleared");
  tasks_.clear();
}

void TaskStack::reject(const Task& task, const std::string& reason, int64_t command_id) {
  emit(TaskEvent::Kind::Rejected, task, command_id, reason);
}

void TaskStack::updateStatuses(int64_t command_id) {
  for (std::size_t i = 1; i < tasks_.size(); ++i) {
    if (tasks_[i].status == Status::Active) {
      tasks_[i].status = Status::Suspended;
      emit(TaskEvent::Kind::Suspended, tasks_[i], command_id);
    }
  }
  if (tasks_.empty()) return;
  Task& top = tasks_.front();
  if (top.status == Status::Pending) {
    top.status = Status::Active;
    emit(TaskEvent::Kind::Started, top, command_id);
  } else if (top.status == Status::Suspended) {
    top.status = Status::Active;
    emit(TaskEvent::Kind::Resumed, top, command_id);
  }
}

}  // namespace beft::tasks
