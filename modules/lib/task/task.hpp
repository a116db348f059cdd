// One task of the task stack (paper section 2.3) and the kinds the executor
// runs itself. Mirrors beft::task_t (task_messages.hpp converts).
#pragma once

#include <cstdint>
#include <string>

namespace beft::tasks {

enum class Status : int8_t { Pending = 0, Active = 1, Suspended = 2, Done = 3, Failed = 4 };

const char* statusName(Status status);

// What each kind reads of a task's fields:
//   goto       x, y [m], yaw [deg] (NaN: any final heading)
//   turn_head  yaw: head pan relative to the platform [deg]
//   turn       yaw: platform heading, world frame [deg]
//   look_at    object_id (position from HYPOTHESES, else AUDIO, else x, y)
//   wait       x: duration [s]
// Any other kind is a composite task owned by the expert that pushed it
// (origin): it stays on the stack while its owner pushes sub-tasks under it,
// and ends when the owner finishes it with a TASK_COMMAND pop naming it.
namespace kinds {
inline constexpr const char* kGoto = "goto";
inline constexpr const char* kTurnHead = "turn_head";
inline constexpr const char* kTurn = "turn";
inline constexpr const char* kLookAt = "look_at";
inline constexpr const char* kWait = "wait";
}  // namespace kinds

// True for the kinds the executor runs itself; the rest are owned by their origin.
bool isBuiltInKind(const std::string& kind);

struct Task {
  int64_t id = 0;      // unique, increasing; assigned by the stack
  int64_t parent = 0;  // task that pushed it, 0 for none
  std::string kind;
  int32_t priority = 0;  // higher interrupts lower
  double x = 0, y = 0, yaw = 0;
  std::string object_id;
  Status status = Status::Pending;
  std::string origin;  // who pushed it: an expert name or "user"
  std::string note;    // human-readable description, or the reason it ended
};

// "goto(12, 8, 90)", "look_at(victim1)", ... for logs and displays.
std::string describe(const Task& task);

}  // namespace beft::tasks
