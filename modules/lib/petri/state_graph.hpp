// The graph of a search's explored states: edges between state indices, and
// the backwards question both analyses ask of it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace beft::arbiter {

struct StateEdge {
  uint32_t from = 0, to = 0;
};

// For each of `states` states: whether one of `targets` is reachable from it
// (a backwards search over the reversed edges; a target reaches itself).
std::vector<bool> reachesAnyOf(std::size_t states, const std::vector<StateEdge>& edges,
                               const std::vector<uint32_t>& targets);

}  // namespace beft::arbiter
