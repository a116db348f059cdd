// Processes killed on purpose (SIGKILL) when the run reaches a tick, to test
// and measure crash-only restarts: `beft-run ... --kill fusion@150`.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <memory>

#include <lcm/lcm-cpp.hpp>

namespace beft::launch {

struct PlannedKill {
  std::string process;
  int64_t tick = 0;
  bool done = false;
};

// "NAME@TICK" -> PlannedKill; throws LaunchError naming what is wrong.
PlannedKill parsePlannedKill(const std::string& text);

// Tells the tick the arbiter has reached, from its MARKING messages on the
// bus (not from the log: the recorder, in the background, may lag seconds
// behind on a loaded machine).
class TickFollower {
 public:
  TickFollower(const std::string& lcm_url, int64_t run_id);
  ~TickFollower();
  // Takes what arrived since the last call; the newest tick seen, -1 if none.
  int64_t poll();

 private:
  static void onMarking(const lcm::ReceiveBuffer* buffer, const std::string& channel, TickFollower* self);
  std::unique_ptr<lcm::LCM> lcm_;
  int64_t tick_ = -1;
};

}  // namespace beft::launch
