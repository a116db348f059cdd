#include "lib/petri/state_graph.hpp"

namespace beft::arbiter {

std::vector<bool> reachesAnyOf(std::size_t states, const std::vector<StateEdge>& edges,
                               const std::vector<uint32_t>& targets) {
  // The reversed edges in compressed rows: sources[offsets[s] .. offsets[s + 1]) lead into s.
  std::vector<uint32_t> offsets(states + 1, 0);
  for (const auto& edge : edges) ++offsets[edge.to + 1];
  for (std::size_t i = 0; i < states; ++i) offsets[i + 1] += offsets[i];
  std::vector<uint32_t> sources(edges.size());
  std::vector<uint32_t> fill(offsets.begin(), offsets.end() - 1);
  for (const auto& edge : edges) sources[fill[edge.to]++] = edge.from;

  std::vector<bool> reaches(states, false);
  std::vector<uint32_t> stack;
  for (uint32_t target : targets) {
    if (reaches[target]) continue;
    reaches[target] = true;
    stack.push_back(target);
  }
  while (!stack.empty()) {
    const uint32_t at = stack.back();
    stack.pop_back();
    for (uint32_t k = offsets[at]; k < offsets[at + 1]; ++k) {
      if (reaches[sources[k]]) continue;
      reaches[sources[k]] = true;
      stack.push_back(sources[k]);
    }
  }
  return reaches;
}

}  // namespace beft::arbiter
