#include "lib/petri/reachability_graph.hpp"

#include "lib/petri/state_graph.hpp"
#include "lib/petri/state_store.hpp"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <set>
#include <unordered_set>

namespace beft::arbiter {

namespace {

constexpr size_t kDeadlockWitnesses = 3;
constexpr int kAncestorsChecked = 256;  // how far up the path a new state looks for one it covers
constexpr uint32_t kNoParent = UINT32_MAX;

enum class EdgeKind : uint8_t { Start, End, Silent };


struct Parent {
  uint32_t state = kNoParent;
  int32_t transition = -1;
  EdgeKind kind = EdgeKind::Silent;
};

class Explorer {
 public:
  Explorer(const Net& net, const ReachabilityOptions& options)
      : net_(net), options_(options), places_(net.places.size()),
        store_(net.places.size() + net.transitions.size()) {
    for (const auto& t : net_.transitions) {
      std::vector<int> same;
      for (size_t u = 0; u < net_.transitions.size(); ++u)
        if (!t.silent() && net_.transitions[u].expert == t.expert) same.push_back(static_cast<int>(u));
      same_expert_.push_back(same);
    }
  }

  ReachabilityReport run() {
    ReachabilityReport report;
    std::vector<int32_t> initial(places_ + net_.transitions.size(), 0);
    for (size_t p = 0; p < places_; ++p) initial[p] = net_.places[p].initial_tokens;
    store_.insert(initial);
    parents_.push_back(Parent{});
    checkSafe(0, report);

    std::vector<bool> fired(net_.transitions.size(), false);
    std::vector<bool> has_successor;
    for (size_t current = 0; current < store_.size(); ++current) {
      if (store_.size() >= options_.max_states || report.unbounded) {
        report.complete = false;
        break;
      }
      bool any = false;
      const std::vector<int32_t> state(store_.at(current), store_.at(current) + places_ + net_.transitions.size());
      for (size_t t = 0; t < net_.transitions.size(); ++t) {
        const Transition& transition = net_.transitions[t];
        if (transition.silent()) {
          if (!enabled(transition, state)) continue;
          auto next = state;
          apply(transition.inputs, next, -1);
          apply(transition.outputs, next, +1);
          addEdge(current, next, static_cast<int>(t), EdgeKind::Silent, report);
          fired[t] = any = true;
          continue;
        }
        if (state[places_ + t] > 0) {  // end of a firing in flight
          auto next = state;
          next[places_ + t] = 0;
          apply(transition.outputs, next, +1);
          addEdge(current, next, static_cast<int>(t), EdgeKind::End, report);
          any = true;
        }
        if (enabled(transition, state) && expertIdle(static_cast<int>(t), state)) {
          auto next = state;
          apply(transition.inputs, next, -1);
          next[places_ + t] = 1;
          addEdge(current, next, static_cast<int>(t), EdgeKind::Start, report);
          fired[t] = any = true;
        }
      }
      if (!any) {
        ++report.num_deadlocks;
        if (report.deadlock_witnesses.size() < kDeadlockWitnesses)
          report.deadlock_witnesses.push_back(witness(current));
      }
    }
    report.num_states = store_.size();
    for (size_t t = 0; t < net_.transitions.size(); ++t)
      if (!fired[t]) report.dead_transitions.push_back(static_cast<int>(t));
    countPlaceMarkings(report);
    checkTickEnd(report);
    return report;
  }

 private:
  bool enabled(const Transition& transition, const std::vector<int32_t>& state) const {
    for (const auto& arc : transition.inputs)
      if (state[arc.place] < arc.weight) return false;
    return true;
  }

  bool expertIdle(int transition, const std::vector<int32_t>& state) const {
    for (int u : same_expert_[transition])
      if (state[places_ + u] > 0) return false;
    return true;
  }

  static void apply(const std::vector<ArcEnd>& arcs, std::vector<int32_t>& state, int sign) {
    for (const auto& arc : arcs) state[arc.place] += sign * arc.weight;
  }

  void addEdge(size_t from, const std::vector<int32_t>& next, int transition, EdgeKind kind,
               ReachabilityReport& report) {
    const auto [index, inserted] = store_.insert(next);
    edges_.push_back(StateEdge{static_cast<uint32_t>(from), index});
    if (!inserted) return;
    parents_.push_back(Parent{static_cast<uint32_t>(from), transition, kind});
    checkSafe(index, report);
    if (!report.unbounded) checkCoversAncestor(index, report);
  }

  // Karp-Miller's argument: if a state covers an ancestor with the same
  // firings in flight, the steps between them can repeat without end.
  void checkCoversAncestor(uint32_t index, ReachabilityReport& report) {
    const int32_t* state = store_.at(index);
    const size_t width = places_ + net_.transitions.size();
    uint32_t ancestor = parents_[index].state;
    for (int depth = 0; depth < kAncestorsChecked && ancestor != kNoParent; ++depth) {
      const int32_t* older = store_.at(ancestor);
      bool covers = std::equal(state + places_, state + width, older + places_);
      int grown = -1;
      for (size_t p = 0; covers && p < places_; ++p) {
        if (state[p] < older[p]) covers = false;
        else if (state[p] > older[p] && grown < 0) grown = static_cast<int>(p);
      }
      if (covers && grown >= 0) {
        report.unbounded = true;
        report.growing_place = grown;
        report.unbounded_witness = witness(index);
        return;
      }
      ancestor = parents_[ancestor].state;
    }
  }

  void checkSafe(uint32_t index, ReachabilityReport& report) {
    if (!report.safe) return;
    const int32_t* state = store_.at(index);
    for (size_t p = 0; p < places_; ++p) {
      if (state[p] > 1) {
        report.safe = false;
        report.unsafe_place = static_cast<int>(p);
        report.unsafe_witness = witness(index);
        return;
      }
    }
  }

  ReachableState witness(size_t index) const {
    ReachableState result;
    const int32_t* state = store_.at(index);
    result.tokens.assign(state, state + places_);
    for (size_t t = 0; t < net_.transitions.size(); ++t)
      if (state[places_ + t] > 0) result.running.push_back(static_cast<int>(t));
    for (uint32_t i = static_cast<uint32_t>(index); parents_[i].state != kNoParent; i = parents_[i].state) {
      const Parent& parent = parents_[i];
      const std::string& id = net_.transitions[parent.transition].id;
      result.trace.push_back(parent.kind == EdgeKind::Start ? "start " + id
                             : parent.kind == EdgeKind::End ? "end " + id
                                                            : id);
    }
    std::reverse(result.trace.begin(), result.trace.end());
    return result;
  }

  void countPlaceMarkings(ReachabilityReport& report) const {
    std::set<std::vector<int32_t>> markings;
    for (size_t i = 0; i < store_.size(); ++i)
      markings.emplace(store_.at(i), store_.at(i) + places_);
    report.num_place_markings = markings.size();
  }

  // Backwards from every state where the tick transition is enabled.
  void checkTickEnd(ReachabilityReport& report) {
    const size_t n = store_.size();
    std::vector<uint32_t> tick_enabled;
    const Transition& tick = net_.transitions[net_.tick_transition];
    for (size_t i = 0; i < n; ++i) {
      const std::vector<int32_t> state(store_.at(i), store_.at(i) + places_);
      if (enabled(tick, state)) tick_enabled.push_back(static_cast<uint32_t>(i));
    }
    const std::vector<bool> reaches = reachesAnyOf(n, edges_, tick_enabled);
    // A partial graph cannot show that no path exists: judge complete ones only.
    if (!report.complete) return;
    for (size_t i = 0; i < n; ++i) {
      if (reaches[i]) continue;
      if (report.num_states_without_tick_end++ == 0) report.no_tick_end_witness = witness(i);
    }
  }

  const Net& net_;
  ReachabilityOptions options_;
  size_t places_;
  StateStore store_;
  std::vector<Parent> parents_;
  std::vector<StateEdge> edges_;
  std::vector<std::vector<int>> same_expert_;
};

}  // namespace

ReachabilityReport exploreReachability(const Net& net, const ReachabilityOptions& options) {
  Explorer explorer(net, options);
  return explorer.run();
}

std::string describeState(const Net& net, const ReachableState& state) {
  std::string text = describeMarking(net, state.tokens);
  if (!state.running.empty()) {
    text += ", running:";
    for (int t : state.running) text += " " + net.transitions[t].expert;
  }
  return text;
}

}  // namespace beft::arbiter
