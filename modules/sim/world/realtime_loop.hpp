// Free-running world (--realtime RATE_HZ): no arbiter; the world steps itself
// at a fixed wall-clock rate, publishing every tick, and takes ROBOT_CMD
// messages between ticks. For live viewing and quick manual tests.
#pragma once

#include <cstdint>
#include <string>

#include "sim/world/world_expert.hpp"

namespace beft::world {

struct RealtimeOptions {
  double rate_hz = 0;    // ticks per wall-clock second; 0: not free-running
  std::string lcm_url;
  int64_t last_tick = -1;  // stop after publishing this tick; -1: at the scenario's end
};

// Runs until the last tick or SIGINT/SIGTERM; returns the exit code. The
// expert must have been started (startUp) already.
int runRealtime(WorldExpert& world, const RealtimeOptions& options);

}  // namespace beft::world
