// Runs an expert live on LCM: FIRE/DONE protocol, heartbeat, catch-up.
#pragma once

#include <string>

#include "lib/expert/expert.hpp"

namespace beft::expert {

struct LiveOptions {
  std::string lcm_url;
  std::string process_name;
  double heartbeat_period_s = 0.5;
  // Longest wait for a firing's inputs before firing without them; 0 (the
  // default): never, so a lockstep run's messages do not depend on the
  // machine's load. A lost input is asked again of the blackboard meanwhile.
  double ready_timeout_s = 0.0;
  double refill_after_s = 1.0;   // waiting this long for inputs asks the blackboard for them again
  double wait_report_s = 5.0;    // how often a long wait for inputs is reported
  bool catch_up = true;          // ask the blackboard for the current state at start
  std::string resume_log;        // restarted after a crash: rebuild the state from this run's log first
};

// Returns the process exit code: 0 after a normal end (signal or end of run).
int runLive(Expert& expert, const LiveOptions& options);

}  // namespace beft::expert
