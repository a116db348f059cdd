#include "lib/task/task.hpp"

#include <cmath>
#include <cstdio>

namespace beft::tasks {

const char* statusName(Status status) {
  switch (status) {
    case Status::Pending: return "pending";
    case Status::Active: return "active";
    case Status::Suspended: return "suspended";
    case Status::Done: return "done";
    case Status::Failed: return "failed";
  }
  return "?";
}

bool isBuiltInKind(const std::string& kind) {
  return kind == kinds::kGoto || kind == kinds::kTurnHead || kind == kinds::kTurn ||
         kind == kinds::kLookAt || kind == kinds::kWait;
}

namespace {
std::string number(double value) {
  if (std::isnan(value)) return "any";
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%g", value);
  return buffer;
}
}  // namespace

std::string describe(const Task& task) {
  const std::string& k = task.kind;
  if (k == kinds::kGoto) return k + "(" + number(task.x) + ", " + number(task.y) + ", " + number(task.yaw) + ")";
  if (k == kinds::kTurnHead || k == kinds::kTurn) return k + "(" + number(task.yaw) + ")";
  if (k == kinds::kWait) return k + "(" + number(task.x) + " s)";
  if (k == kinds::kLookAt) return k + "(" + (task.object_id.empty() ? number(task.x) + ", " + number(task.y) : task.object_id) + ")";
  return k + "(" + (task.object_id.empty() ? "" : task.object_id) + ")";
}

}  // namespace beft::tasks
