// Finding the run on a URL for a process or tool started by hand (an expert
// debugged on its own, beft task): the runs whose processes send heartbeats
// there. A process the launcher starts has its run id already.
#pragma once

#include <cstdint>
#include <set>
#include <string>

namespace lcm {
class LCM;
}

namespace beft::wire {

// The run ids of the HEARTBEATs heard within `seconds` (0: a run without id).
std::set<int64_t> runsHeard(lcm::LCM& lcm, double seconds);

// Unless this process has a run id (BEFT_RUN_ID, --run-id), listens for up
// to `seconds` and takes the one run heard (none: the plain channel names).
// Returns "" or, when several runs share the URL, what to tell the user.
std::string adoptTheRunHeard(lcm::LCM& lcm, double seconds);

}  // namespace beft::wire
