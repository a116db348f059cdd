// Offline analysis of a net: explores every reachable state and reports
// whether the net is 1-safe, which transitions can never fire, which states
// are deadlocks, and whether the end of a tick (the tick transition enabled)
// stays reachable from every reachable state.
//
// The model is the arbiter's: an expert transition is two events, start
// (consumes its inputs) and end (produces its outputs), so concurrent
// firings are explored in every interleaving; an expert runs one firing at a
// time; silent transitions, the tick included, fire atomically.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "lib/petri/petri_net.hpp"

namespace beft::arbiter {

struct ReachabilityOptions {
  size_t max_states = 1000000;  // exploration stops there (the report says so)
};

// A reachable state and the shortest way to it from the initial marking.
struct ReachableState {
  Marking tokens;                      // per place
  std::vector<int> running;            // expert transitions in flight
  std::vector<std::string> trace;      // "start t_vision", "end t_vision", "t_join", ...
};

struct ReachabilityReport {
  size_t num_states = 0;               // markings of the places + firings in flight
  size_t num_place_markings = 0;       // distinct markings of the places alone
  bool complete = true;                // false when exploration stopped early
  // Proven unbounded: a state covers one of its ancestors (same firings in
  // flight, at least as many tokens everywhere, more somewhere), so the same
  // steps can repeat for ever. Exploration stops there.
  bool unbounded = false;
  int growing_place = -1;
  std::optional<ReachableState> unbounded_witness;
  bool safe = true;                    // no place ever holds more than one token
  int unsafe_place = -1;
  std::optional<ReachableState> unsafe_witness;
  std::vector<int> dead_transitions;   // can never fire (start) from the initial marking
  size_t num_deadlocks = 0;            // states with nothing enabled and nothing running
  std::vector<ReachableState> deadlock_witnesses;  // the first few
  size_t num_states_without_tick_end = 0;  // states from which the tick can never end
                                           // (judged only when the exploration completed)
  std::optional<ReachableState> no_tick_end_witness;

  // The cycle is live: the exploration completed, no transition is dead and
  // the tick end is reachable from every reachable state (so no deadlock).
  bool live() const { return complete && dead_transitions.empty() && num_states_without_tick_end == 0; }
  bool ok() const { return safe && live(); }
};

ReachabilityReport exploreReachability(const Net& net, const ReachabilityOptions& options = {});

// "p_a=1 p_b=2, running: vision audio"
std::string describeState(const Net& net, const ReachableState& state);

}  // namespace beft::arbiter
