// Karp and Miller's coverability graph of a P/T net: markings where a place
// may hold omega (as many tokens as wanted), found by firing from the
// initial marking and, whenever a new marking covers one on its own path,
// raising the places that grew to omega. It is finite for every net, and
// its markings cover exactly what reachable markings cover, so it decides
// what a search of the reachable markings cannot when they are infinite or
// too many: which places are bounded and by how much, and which transitions
// can ever fire (a transition enabled at a covering marking is enabled at a
// reachable one). Murata's variant: a marking met again is not expanded.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "lib/petri/petri_net.hpp"

namespace beft::arbiter {

struct Coverability {
  bool complete = false;  // false: stopped at max_nodes
  size_t nodes = 0;
  std::vector<std::optional<int>> max_tokens;  // per place; nullopt: unbounded
  std::vector<bool> can_fire;                   // per transition
};

Coverability coverabilityGraph(const Net& net, size_t max_nodes);

}  // namespace beft::arbiter
