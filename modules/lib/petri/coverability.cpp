#include "lib/petri/coverability.hpp"

#include <cstdint>
#include <limits>

#include "lib/petri/state_store.hpp"

namespace beft::arbiter {

namespace {

constexpr int32_t kOmega = std::numeric_limits<int32_t>::max();
constexpr int32_t kTokenCeiling = 1 << 30;  // beyond it the search stops: no overflow
constexpr uint32_t kNoParent = std::numeric_limits<uint32_t>::max();

bool enabledAt(const Transition& transition, const int32_t* marking) {
  for (const auto& arc : transition.inputs)
    if (marking[arc.place] != kOmega && marking[arc.place] < arc.weight) return false;
  return true;
}

}  // namespace

Coverability coverabilityGraph(const Net& net, size_t max_nodes) {
  const size_t places = net.places.size();
  Coverability result;
  result.can_fire.assign(net.transitions.size(), false);
  std::vector<int64_t> highest(places, 0);
  std::vector<bool> omega(places, false);

  StateStore store(places);
  std::vector<uint32_t> parent;
  const auto remember = [&](const Marking& marking, uint32_t from) {
    const auto [index, is_new] = store.insert(marking);
    if (is_new) {
      parent.push_back(from);
      for (size_t p = 0; p < places; ++p) {
        if (marking[p] == kOmega) omega[p] = true;
        else highest[p] = std::max<int64_t>(highest[p], marking[p]);
      }
    }
    return is_new;
  };
  remember(net.initialMarking(), kNoParent);

  bool stopped = false;
  for (size_t next = 0; next < store.size() && !stopped; ++next) {
    const Marking marking(store.at(next), store.at(next) + places);
    for (size_t t = 0; t < net.transitions.size() && !stopped; ++t) {
      const Transition& transition = net.transitions[t];
      if (!enabledAt(transition, marking.data())) continue;
      result.can_fire[t] = true;
      Marking successor = marking;
      for (const auto& arc : transition.inputs)
        if (successor[arc.place] != kOmega) successor[arc.place] -= arc.weight;
      for (const auto& arc : transition.outputs)
        if (successor[arc.place] != kOmega) successor[arc.place] += arc.weight;
      // Acceleration: every place that grew past an ancestor it covers is omega.
      for (uint32_t at = static_cast<uint32_t>(next); at != kNoParent; at = parent[at]) {
        const int32_t* earlier = store.at(at);
        bool covers = true, strictly = false;
        for (size_t p = 0; p < places && covers; ++p) {
          if (successor[p] < earlier[p]) covers = false;
          else if (successor[p] > earlier[p]) strictly = true;
        }
        if (!covers || !strictly) continue;
        for (size_t p = 0; p < places; ++p)
          if (successor[p] > earlier[p]) successor[p] = kOmega;
      }
      for (size_t p = 0; p < places; ++p)
        if (successor[p] != kOmega && successor[p] > kTokenCeiling) stopped = true;
      if (stopped) break;
      if (remember(successor, static_cast<uint32_t>(next)) && store.size() >= max_nodes) stopped = true;
    }
  }
  result.complete = !stopped;
  result.nodes = store.size();
  result.max_tokens.resize(places);
  for (size_t p = 0; p < places; ++p)
    if (!omega[p]) result.max_tokens[p] = static_cast<int>(highest[p]);
  return result;
}

}  // namespace beft::arbiter
