#include "lib/petri/net_analysis.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <random>

#include "lib/petri/coverability.hpp"
#include "lib/petri/state_graph.hpp"
#include "lib/petri/state_store.hpp"

namespace beft::arbiter {

namespace {

constexpr uint32_t kNoParent = std::numeric_limits<uint32_t>::max();
// A marking with a place past this stops the search: no int32 overflow.
constexpr int32_t kTokenCeiling = 1 << 30;

struct Parent {
  uint32_t marking = kNoParent;
  int32_t transition = -1;
};

class Explorer {
 public:
  Explorer(const Net& net, const NetAnalysisOptions& options)
      : net_(net), options_(options), store_(net.places.size()), stop_at_(options.max_markings) {}

  NetAnalysis run() {
    result_.max_tokens.assign(net_.places.size(), 0);
    result_.fired.assign(net_.transitions.size(), false);
    add(net_.initialMarking(), Parent{});
    bool stopped = false;
    for (size_t next = 0; next < store_.size(); ++next) {
      if (!expand(static_cast<uint32_t>(next))) {
        stopped = true;
        break;
      }
    }
    result_.markings = store_.size();
    result_.edges = edges_.size();
    result_.complete = !stopped && !result_.unbounded_witness;
    if (result_.complete) {
      result_.place_bounds.emplace(result_.max_tokens.begin(), result_.max_tokens.end());
      std::vector<int> dead;
      for (size_t t = 0; t < result_.fired.size(); ++t)
        if (!result_.fired[t]) dead.push_back(static_cast<int>(t));
      result_.dead_transitions = dead;
      result_.deadlock = result_.deadlock.value_or(false);
      result_.reversible = initialReachableFromAll();
    } else {
      decideByCoverability();
      if (!result_.deadlock) huntDeadlockByRandomWalks();
      // A deadlock other than the initial marking never leads back to it.
      if (result_.deadlock.value_or(false) && result_.deadlock_marking != net_.initialMarking())
        result_.reversible = false;
    }
    if (result_.unbounded_witness) {
      result_.bounded = false;
    } else if (result_.place_bounds) {
      result_.bounded = std::all_of(result_.place_bounds->begin(), result_.place_bounds->end(),
                                    [](const std::optional<int>& b) { return b.has_value(); });
    }
    return std::move(result_);
  }

 private:
  // When the search could not finish, a deadlock may lie deeper than it
  // went: seeded random firing sequences (the same every run) look for one.
  // A deadlock found this way is real, its trace is just not the shortest.
  void huntDeadlockByRandomWalks() {
    std::mt19937_64 random(options_.walk_seed);
    const size_t steps_per_walk = std::max<size_t>(1000, options_.max_markings / 1000);
    size_t steps_left = options_.max_markings;
    std::vector<int> enabled, trace;
    while (steps_left > 0) {
      Marking marking = net_.initialMarking();
      trace.clear();
      for (size_t step = 0; step < steps_per_walk && steps_left > 0; ++step, --steps_left) {
        enabled.clear();
        for (size_t t = 0; t < net_.transitions.size(); ++t)
          if (isEnabled(net_.transitions[t], marking)) enabled.push_back(static_cast<int>(t));
        if (enabled.empty()) {
          result_.deadlock = true;
          result_.deadlock_trace = trace;
          result_.deadlock_marking = marking;
          result_.deadlock_by_random_walk = true;
          return;
        }
        const int t = enabled[std::uniform_int_distribution<size_t>(0, enabled.size() - 1)(random)];
        consumeInputs(net_.transitions[t], marking);
        produceOutputs(net_.transitions[t], marking);
        result_.fired[t] = true;
        trace.push_back(t);
        if (std::any_of(marking.begin(), marking.end(), [](int tokens) { return tokens > kTokenCeiling; })) break;
      }
    }
  }

  void decideByCoverability() {
    // A tenth of the budget: the graph is small when places grow (omega
    // folds them), and as large as the search when they do not.
    const Coverability graph = coverabilityGraph(net_, std::max<size_t>(1000, options_.max_markings / 10));
    result_.coverability_nodes = graph.nodes;
    if (!graph.complete) return;
    result_.place_bounds = graph.max_tokens;
    std::vector<int> dead;
    for (size_t t = 0; t < graph.can_fire.size(); ++t)
      if (!graph.can_fire[t]) dead.push_back(static_cast<int>(t));
    result_.dead_transitions = dead;
  }

  Marking markingAt(uint32_t index) const {
    const int32_t* row = store_.at(index);
    return Marking(row, row + net_.places.size());
  }

  std::vector<int> traceTo(uint32_t index) const {
    std::vector<int> trace;
    for (uint32_t at = index; parents_[at].marking != kNoParent; at = parents_[at].marking)
      trace.push_back(parents_[at].transition);
    std::reverse(trace.begin(), trace.end());
    return trace;
  }

  // Returns the index; records a new marking's parent and its tokens.
  std::pair<uint32_t, bool> add(const Marking& marking, Parent parent) {
    const auto [index, is_new] = store_.insert(marking);
    if (!is_new) return {index, false};
    parents_.push_back(parent);
    for (size_t p = 0; p < marking.size(); ++p) result_.max_tokens[p] = std::max(result_.max_tokens[p], marking[p]);
    return {index, true};
  }

  // Fires every enabled transition of one marking; false to stop the search.
  bool expand(uint32_t index) {
    const Marking marking = markingAt(index);
    bool any_enabled = false;
    for (size_t t = 0; t < net_.transitions.size(); ++t) {
      const Transition& transition = net_.transitions[t];
      if (!isEnabled(transition, marking)) continue;
      any_enabled = true;
      result_.fired[t] = true;
      Marking next = marking;
      consumeInputs(transition, next);
      produceOutputs(transition, next);
      if (std::any_of(next.begin(), next.end(), [](int tokens) { return tokens > kTokenCeiling; })) return false;
      const auto [to, is_new] = add(next, Parent{index, static_cast<int32_t>(t)});
      edges_.push_back({index, to});
      if (is_new && !result_.unbounded_witness) {
        checkCovers(to);
        if (result_.unbounded_witness) stop_at_ = std::min(options_.max_markings, store_.size() + options_.max_markings / 100);
      }
      if (store_.size() >= stop_at_ && is_new) return false;
    }
    if (!any_enabled && !result_.deadlock) {
      result_.deadlock = true;
      result_.deadlock_trace = traceTo(index);
      result_.deadlock_marking = marking;
    }
    return true;
  }

  // Karp-Miller: does the new marking cover one on its own path?
  void checkCovers(uint32_t index) {
    const int32_t* now = store_.at(index);
    const size_t places = net_.places.size();
    size_t depth = 0;
    for (uint32_t at = parents_[index].marking; at != kNoParent; at = parents_[at].marking, ++depth) {
      const int32_t* earlier = store_.at(at);
      bool covers = true, strictly = false;
      for (size_t p = 0; p < places && covers; ++p) {
        if (now[p] < earlier[p]) covers = false;
        if (now[p] > earlier[p]) strictly = true;
      }
      if (!covers || !strictly) continue;
      NetAnalysis::Unbounded witness;
      witness.trace = traceTo(index);
      witness.covered_after = witness.trace.size() - depth - 1;
      witness.covered = markingAt(at);
      witness.covering = markingAt(index);
      for (size_t p = 0; p < places; ++p)
        if (now[p] > earlier[p]) witness.growing_places.push_back(static_cast<int>(p));
      result_.unbounded_witness = std::move(witness);
      return;
    }
  }

  // Backwards from the initial marking: does every marking reach it?
  bool initialReachableFromAll() const {
    const std::vector<bool> reaches = reachesAnyOf(store_.size(), edges_, {0});
    return std::all_of(reaches.begin(), reaches.end(), [](bool r) { return r; });
  }

  const Net& net_;
  const NetAnalysisOptions& options_;
  StateStore store_;
  std::vector<Parent> parents_;
  std::vector<StateEdge> edges_;
  size_t stop_at_;  // markings after which the search stops
  NetAnalysis result_;
};

}  // namespace

std::optional<int> NetAnalysis::bound() const {
  if (!place_bounds) return std::nullopt;
  int k = 0;
  for (const auto& b : *place_bounds) {
    if (!b) return std::nullopt;
    k = std::max(k, *b);
  }
  return k;
}

std::optional<bool> NetAnalysis::safe() const {
  if (std::any_of(max_tokens.begin(), max_tokens.end(), [](int tokens) { return tokens > 1; })) return false;
  if (!place_bounds) return std::nullopt;
  for (const auto& b : *place_bounds)
    if (!b || *b > 1) return false;
  return true;
}

NetAnalysis analyseNet(const Net& net, const NetAnalysisOptions& options) {
  return Explorer(net, options).run();
}

}  // namespace beft::arbiter
