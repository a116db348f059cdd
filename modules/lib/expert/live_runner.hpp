// Runs an expert live on LCM: FIRE/DONE protocol, heartbeat, catch-up.
#pragma once

#include <string>

#include "expert.hpp"

namespace beft::expert {

struct LiveOptions {
  std::string lcm_url;
  std::string process_name;
  double heartbeat_period_s = 0.5;
  double ready_timeout_s = 2.0;  // longest wait for a firing's inputs
  bool catch_up = true;          // ask the blackboard for the current state at start
  std::string resume_log;        // restarted after a crash: rebuild the state from this run's log first
};

// Returns the process exit code: 0 after a normal end (signal or end of run).
int runLive(Expert& expert, const LiveOptions& options);

}  // namespace beft::expert
