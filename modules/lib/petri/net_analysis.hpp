// Analysis of any place/transition net under the standard firing rule (a
// transition fires atomically: consumes its inputs, produces its outputs),
// annotated for the arbiter or not.
//
// A breadth-first search of the reachable markings keeps, for each marking,
// the transition and marking it was first reached by, so every witness is a
// shortest firing sequence. Unboundedness is proven as in Karp and Miller's
// coverability tree: a new marking M' that covers a marking M on its own
// path (M' >= M, M' != M) lets the same steps repeat for ever, each time
// adding M' - M; after such a proof the search goes on for a hundredth of
// its budget, to find deadlocks near the start, and stops. The search stops
// at max_markings; when it did not complete, Karp and Miller's coverability
// graph (coverability.hpp; a tenth of the budget) decides the bound of every place and which
// transitions can fire, and seeded random firing sequences (as many steps as
// the search's budget) look for a deadlock deeper than the search went.
// What none of them could decide is "unknown".
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "lib/petri/petri_net.hpp"

namespace beft::arbiter {

struct NetAnalysisOptions {
  size_t max_markings = 1000000;  // the search stops there (complete = false)
  uint64_t walk_seed = 1;         // of the random walks that hunt a deadlock when the search stops
};

struct NetAnalysis {
  size_t markings = 0;       // distinct reachable markings explored
  size_t edges = 0;          // firings between them
  bool complete = false;     // every reachable marking explored
  std::optional<bool> bounded;  // unknown when incomplete without a proof of unboundedness

  // Proof of unboundedness: firing `trace` from the initial marking reaches
  // `covering`; after its first `covered_after` steps it was at `covered`,
  // which `covering` exceeds in `growing_places`.
  struct Unbounded {
    std::vector<int> trace;
    size_t covered_after = 0;
    Marking covered, covering;
    std::vector<int> growing_places;
  };
  std::optional<Unbounded> unbounded_witness;

  std::vector<int> max_tokens;  // per place, over the markings explored
  // The most tokens each place can hold (an empty entry: unbounded), when
  // known: from the complete search or the coverability graph.
  std::optional<std::vector<std::optional<int>>> place_bounds;
  size_t coverability_nodes = 0;  // 0 when the graph was not needed
  std::optional<int> bound() const;  // k of k-safe: the largest place bound, when all are bounded
  std::optional<bool> safe() const;  // 1-safe; unknown when nothing decides it

  // A reachable marking where no transition is enabled, by the shortest way
  // the search found; unknown (nullopt) when incomplete and none was found.
  std::optional<bool> deadlock;
  std::vector<int> deadlock_trace;  // transition indices
  Marking deadlock_marking;
  bool deadlock_by_random_walk = false;  // found past the search: a real trace, maybe not the shortest

  std::vector<bool> fired;  // per transition: fired somewhere in the part explored
  // Transitions that can never fire, when known (the complete search, or
  // the coverability graph).
  std::optional<std::vector<int>> dead_transitions;

  // The initial marking reachable from every reachable marking; known when
  // the search completed, or false when it found a deadlock elsewhere.
  std::optional<bool> reversible;
};

NetAnalysis analyseNet(const Net& net, const NetAnalysisOptions& options = {});

}  // namespace beft::arbiter
