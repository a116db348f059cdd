// Starts the processes of a launch file, prefixes their output with their
// names, restarts them per policy, and stops them all at the end.
#pragma once

#include <functional>
#include <set>
#include <string>
#include <vector>

#include "lib/launch/fault_injection.hpp"
#include "lib/launch/launch_file.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::launch {

struct SupervisorOptions {
  std::string lcm_url;
  std::string host = "local";         // processes with another host label are not started
  std::set<std::string> except;       // processes not to start (started by hand)
  std::string bin_dir;                // where commands are looked up first
  std::string record_log;             // if set, beft-record records the run here
  std::string record_exclude_regex;   // channels the logger leaves out
  std::string record_camera = "all";  // camera frames the logger keeps: all, none, every:N (beft-record --camera)
  double stop_grace_s = 3.0;          // SIGTERM, then SIGKILL after this
  bool quiet_children = false;        // do not echo children's output
  std::string output_file;            // also append every prefixed line here
  std::vector<PlannedKill> kills;     // fault injection: SIGKILL a process when the run reaches a tick
  int64_t run_id = 0;                 // given to every process as BEFT_RUN_ID (0: none)
  std::string key_file;               // absolute path of the run's key (run_key.hpp), given to every process as
                                      // BEFT_KEY_FILE; "": a run without a key (BEFT_KEY_FILE is then unset)
  wire::RunOrigin run_origin;         // the launch and its time, for the arbiter's beacons (launch_identity.hpp)
};

struct RunOutcome {
  bool arbiter_ran = false;
  int arbiter_exit_code = -1;  // -1: never exited by itself
  bool interrupted = false;    // stopped by a signal
  bool log_incomplete = false; // the recorder died: the run was stopped, its log misses what came after
  std::string message;
};

// Runs until the arbiter process exits (then stops the rest), every process
// has exited, or SIGINT/SIGTERM. Returns what happened.
RunOutcome supervise(const LaunchSpec& spec, const SupervisorOptions& options);

// The command line a user would type to start a process by hand.
std::string commandLineOf(const ProcessSpec& process, const SupervisorOptions& options);

}  // namespace beft::launch
