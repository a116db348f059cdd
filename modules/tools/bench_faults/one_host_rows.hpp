// The rows of beft-bench-faults on this machine, each a yard run by
// beft-run compared with the clean run: malformed traffic, another run's
// messages, every expert killed once, an earlier run's log played on the
// URL at full speed, and a keyed run with an unkeyed publisher beside it.
#pragma once

#include <string>
#include <vector>

#include "lib/compare/run_log.hpp"
#include "tools/bench_faults/outcome.hpp"

namespace beft::bench {

struct OneHostRuns {
  std::string work;       // each run in a folder of its own here
  std::string clean_log;  // the clean run's log, recorded just before (same scenario and seed)
  int ticks = 0;
  std::string kills;      // beft-run arguments that kill every expert once
};

std::vector<Outcome> runOnOneHost(const OneHostRuns& runs, const std::vector<compare::LoggedMessage>& clean);

}  // namespace beft::bench
