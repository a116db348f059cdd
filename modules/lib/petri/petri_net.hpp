// The arbiter's Petri net: a P/T net whose transitions are expert firings.
//
// Each expert transition is a start -> exec -> end action (Petri Net Plans):
// starting it consumes its input tokens and sends FIRE; DONE ends it and
// produces its output tokens. Silent transitions (joins, forks, the tick) fire
// atomically. Exactly one silent transition is the tick transition: firing it
// closes tick k and opens tick k + 1.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace beft::arbiter {

// What the arbiter does when a firing times out, its expert stops sending
// heartbeats, or the expert answers DONE with a failure.
enum class ExpiryAction { Retry, Skip, Fail };
const char* actionName(ExpiryAction action);

struct FiringPolicy {
  double timeout_s = 10.0;            // wall time from FIRE to DONE
  double heartbeat_timeout_s = 0.0;   // <= 0: the arbiter's default
  ExpiryAction on_timeout = ExpiryAction::Fail;  // also applies to a lost heartbeat
  ExpiryAction on_failure = ExpiryAction::Fail;  // DONE with OUTCOME_FAILED
  int retries = 0;                    // new firings after the first, shared by both
  ExpiryAction after_retries = ExpiryAction::Fail;  // Skip or Fail once retries are spent
};

struct Place {
  std::string id;
  std::string name;        // display name, may be empty
  int initial_tokens = 0;
  int line = 0;            // line in the PNML file
};

struct ArcEnd {
  int place = 0;   // index into Net::places
  int weight = 1;
};

struct Transition {
  std::string id;
  std::string name;        // display name, may be empty
  std::string expert;      // empty for a silent transition
  std::string level;       // free label from the net (world, low, mid, high)
  bool is_tick = false;
  FiringPolicy policy;
  std::vector<ArcEnd> inputs;
  std::vector<ArcEnd> outputs;
  int line = 0;

  bool silent() const { return expert.empty(); }
};

using Marking = std::vector<int>;  // tokens per place, in Net::places order

struct Net {
  std::string id;
  std::string name;
  std::string file;                  // where it was read from, for messages
  std::vector<Place> places;
  std::vector<Transition> transitions;
  int tick_transition = -1;          // index into transitions
  std::vector<std::string> warnings; // things worth a look that are not errors
  // Read as any P/T net: what keeps it from being an arbiter schedule
  // (a transition naming no expert, no tick transition, ...), "FILE:LINE: ...".
  std::vector<std::string> schedule_problems;
  bool annotated = false;            // some node carries the arbiter's <toolspecific tool="beft">

  size_t arcCount() const;

  Marking initialMarking() const;
  // Distinct expert names in order of first appearance.
  std::vector<std::string> experts() const;
  int placeIndex(const std::string& id) const;       // -1 if none
  int transitionIndex(const std::string& id) const;  // -1 if none
};

bool isEnabled(const Transition& transition, const Marking& marking);
void consumeInputs(const Transition& transition, Marking& marking);
void produceOutputs(const Transition& transition, Marking& marking);

// "p_tick_start=1 p_vision_in=1": the marked places only ("empty" if none).
std::string describeMarking(const Net& net, const Marking& marking);

}  // namespace beft::arbiter
