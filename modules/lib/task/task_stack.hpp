// The task stack (paper section 2.3): tasks ordered by priority, top first.
// A task of higher priority than the top interrupts it (the top is suspended
// and resumes once the new one is gone); a task of equal or lower priority
// goes below every task of higher or equal priority, so equals run in the
// order pushed. A sub-task (parent set) runs at least at its parent's
// priority and goes directly above its parent, below the parent's earlier
// sub-tasks: a composite task pushes its steps in the order they run, and
// resumes when they are all gone. Plain logic, no LCM.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "lib/task/task.hpp"

namespace beft::tasks {

struct TaskEvent {
  enum class Kind { Pushed, Rejected, Started, Suspended, Resumed, Done, Failed, Removed };
  Kind kind;
  Task task;               // the task after the event
  int64_t command_id = 0;  // the command that caused it, 0 for the executor
  std::string reason;
};

const char* eventName(TaskEvent::Kind kind);
// One line for a log: "done 3 goto(12, 8, 90) from user (command 7): reached ...".
std::string describeEvent(const TaskEvent& event);

struct StackOptions {
  // A failed sub-task fails its parent (and so on up), like a sequence in a
  // behaviour tree. Off: the parent resumes and its owner decides.
  bool child_failure_fails_parent = true;
  std::size_t max_tasks = 256;  // pushes beyond this are rejected
};

// Why a task cannot be pushed (empty if it can): a missing kind, or a
// built-in kind whose fields are not finite or out of range.
std::string validateTask(const Task& task);

class TaskStack {
 public:
  explicit TaskStack(StackOptions options = {}) : options_(options) {}

  // Pushes a task; its id and status are assigned here. Returns the new id, or
  // 0 when rejected (the Rejected event says why). A sub-task's priority is
  // raised to its parent's.
  int64_t push(Task task, int64_t command_id = 0);
  // Ends a task as Done or Failed, with its sub-tasks (Removed). Returns false
  // if no such task is on the stack.
  bool finish(int64_t id, Status outcome, const std::string& reason, int64_t command_id = 0);
  // Cancels a task and its sub-tasks (Removed); its parent, if any, resumes.
  bool remove(int64_t id, const std::string& reason, int64_t command_id = 0);
  // Cancels the top task. False on an empty stack.
  bool pop(int64_t command_id = 0);
  // Cancels every task.
  void clear(int64_t command_id = 0);
  // Records that a command could not be applied (a Rejected event).
  void reject(const Task& task, const std::string& reason, int64_t command_id = 0);

  const std::vector<Task>& tasks() const { return tasks_; }  // top first
  bool empty() const { return tasks_.empty(); }
  const Task* top() const { return tasks_.empty() ? nullptr : &tasks_.front(); }
  const Task* find(int64_t id) const;
  bool hasSubTasks(int64_t id) const;
  bool isDescendant(int64_t id, int64_t ancestor) const;

  // Events since the last call, oldest first.
  std::vector<TaskEvent> takeEvents();
  // The events takeEvents() would return now.
  const std::vector<TaskEvent>& pendingEvents() const { return events_; }

 private:
  int indexOf(int64_t id) const;
  void emit(TaskEvent::Kind kind, const Task& task, int64_t command_id, std::string reason = {});
  // Removes the sub-tasks of id (Removed events), leaves id itself.
  void removeSubTasks(int64_t id, const std::string& reason, int64_t command_id);
  // The top is Active; others that ran are Suspended.
  void updateStatuses(int64_t command_id);

  StackOptions options_;
  std::vector<Task> tasks_;
  std::vector<TaskEvent> events_;
  int64_t next_id_ = 1;
};

}  // namespace beft::tasks
