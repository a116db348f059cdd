// When each tick of a run started, from its log: the receive time of the
// tick's first FIRE, and of the run's last DONE. The lockstep loop's speed
// over any stretch of ticks follows (report.json gives only the whole run's).
#pragma once

#include <cstdint>
#include <map>
#include <string>

namespace beft::bench {

struct TickTimes {
  std::map<int64_t, int64_t> first_fire_us;  // tick -> receive time of its first FIRE [us since the epoch]
  int64_t last_done_us = -1;

  // The first tick whose first FIRE came at or after `since_us`; -1 if none.
  int64_t firstTickFiredAfter(int64_t since_us) const;
  // The tick under way at `at_us` (the last one fired by then); -1 before the first.
  int64_t tickAt(int64_t at_us) const;
  // Ticks per second from tick `from` on (its first FIRE to the last DONE); 0 when unknown.
  double ticksPerSecondFrom(int64_t from) const;
};

// Reads the FIREs and DONEs of the run in `log_path`; empty when it cannot be read.
TickTimes readTickTimes(const std::string& log_path);

}  // namespace beft::bench
