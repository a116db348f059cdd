// The runs of beft-bench-faults: yard.xml by beft-run, and the programs
// that make a fault beside it (an injector, a log player), each a shell
// command in a process group of its own.
#pragma once

#include <sys/types.h>

#include <functional>
#include <string>

#include "tools/bench_faults/outcome.hpp"

namespace beft::bench {

// Starts `command` through sh in a process group of its own.
pid_t startShell(const std::string& command);
// Ends what startShell started, the whole group (SIGTERM), and waits for it.
void stopShell(pid_t pid);
// Runs `command` through sh to its end, or ends it after `timeout_s`; its
// exit code, -1 when it was ended for time.
int runShell(const std::string& command, double timeout_s);

// What runs beside a run once its URL and run id are printed (the process
// group startShell started, stopped when the run ends).
using During = std::function<pid_t(const std::string& url, const std::string& run_id)>;

// One yard run of `ticks` ticks by beft-run with `args`, in `dir` (made
// anew), with `during` beside it; its outcome, not yet compared.
Outcome runYard(const std::string& name, const std::string& dir, const std::string& args, int ticks,
                const During& during);

}  // namespace beft::bench
