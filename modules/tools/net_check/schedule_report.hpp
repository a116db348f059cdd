// The BEFT checks of a net that is an arbiter schedule: the arbiter's model
// (an expert transition is start + end, an expert runs one firing at a
// time), 1-safe, no dead transition, the tick end reachable from every
// reachable state.
#pragma once

#include "lib/petri/petri_net.hpp"
#include "lib/petri/reachability_graph.hpp"

namespace beft::net_check {

void printScheduleSummary(const arbiter::Net& net, const std::string& path);
// Prints the exploration; returns 0 when 1-safe and live, else 1 (the reasons printed).
int printScheduleChecks(const arbiter::Net& net, const arbiter::ReachabilityReport& report,
                        const arbiter::ReachabilityOptions& options);

}  // namespace beft::net_check
