// What `beft net check` says of any P/T net: as text for a person, or as
// one JSON object for a program.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "lib/petri/net_analysis.hpp"
#include "lib/petri/petri_net.hpp"

namespace beft::net_check {

void printAnalysis(const arbiter::Net& net, const arbiter::NetAnalysis& analysis,
                   const arbiter::NetAnalysisOptions& options);

// Keys: places, transitions, arcs, markings, complete, bounded, max_tokens,
// safe, deadlock, deadlock_trace, dead_transitions, reversible (null where
// unknown), and the details: net, file, max_tokens_per_place,
// max_tokens_seen, unbounded_witness, not_fired_so_far, warnings.
nlohmann::json analysisJson(const arbiter::Net& net, const arbiter::NetAnalysis& analysis);

// "t1, t2, t3" of transition ids; a long trace shows its start and its end.
std::string traceText(const arbiter::Net& net, const std::vector<int>& trace);

}  // namespace beft::net_check
