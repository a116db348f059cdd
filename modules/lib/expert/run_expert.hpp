// The process around an expert: command line, LCM, FIRE/DONE, heartbeat.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "lib/expert/expert.hpp"

namespace CLI {
class App;
}

namespace beft::expert {

// The whole main() of an expert process:
//   int main(int argc, char** argv) { MyExpert e; return beft::expert::runExpertMain(argc, argv, e); }
// Flags: --help, --interface (prints what it reads and writes), --lcm-url,
// --name (process name, default expert.name()), --param key=value (repeat),
// --heartbeat-period seconds, --replay LOG (offline against a recorded log:
// feeds the logged inputs in order, fires at every logged FIRE for this
// expert, compares the outputs with the logged ones and prints the result).
// Live: subscribes to reads() and FIRE; for each new FIRE addressed to it
// (firing_id greater than any it ran) waits until inputsReady (bounded), runs
// fire(), publishes DONE. A FIRE it already ran gets its DONE again (the first
// may have been lost); an older one is logged and dropped. Sends HEARTBEAT
// every period. Exits on SIGINT/SIGTERM or when RUN_STATUS says the run ended.
// Unknown --param names and values out of a parameter's range are refused.
int runExpertMain(int argc, char** argv, Expert& expert);

// The same, for a process with options of its own (e.g. the world's
// --scenario): add_options adds them to the command line before parsing; the
// variables they bind are set before startUp is called. run_instead, if
// given, is asked after start-up (with the --lcm-url given): an exit code means the process ran some
// other way (the world's free-running mode) instead of waiting for FIREs.
int runExpertMain(int argc, char** argv, Expert& expert, const std::function<void(CLI::App&)>& add_options,
                  const std::function<std::optional<int>(const std::string& lcm_url)>& run_instead = {});

}  // namespace beft::expert
