// Processes killed on purpose (SIGKILL) when the run reaches a tick, to test
// and measure crash-only restarts: `beft-run ... --kill fusion@150`.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "log_reader.hpp"

namespace beft::launch {

struct PlannedKill {
  std::string process;
  int64_t tick = 0;
  bool done = false;
};

// "NAME@TICK" -> PlannedKill; throws LaunchError naming what is wrong.
PlannedKill parsePlannedKill(const std::string& text);

// Follows the run's log as the recorder writes it and tells the tick the
// arbiter has reached (its RUN_STATUS and MARKING messages).
class TickFollower {
 public:
  TickFollower(std::string log_path, int64_t run_id) : path_(std::move(log_path)), run_id_(run_id) {}
  // Reads what was added since the last call; the newest tick seen, -1 if none.
  int64_t poll();

 private:
  std::string path_;
  int64_t run_id_;
  uint64_t offset_ = 0;
  int64_t tick_ = -1;
};

}  // namespace beft::launch
