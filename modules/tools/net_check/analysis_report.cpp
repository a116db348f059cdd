#include "tools/net_check/analysis_report.hpp"

#include <algorithm>
#include <cstdio>

namespace beft::net_check {

using namespace arbiter;

namespace {

constexpr size_t kTraceHead = 24;
constexpr size_t kTraceTail = 8;

const char* yesNoUnknown(const std::optional<bool>& value, const char* yes = "yes", const char* no = "NO") {
  return !value ? "unknown (search incomplete)" : *value ? yes : no;
}

template <typename Value>
nlohmann::json orNull(const std::optional<Value>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

nlohmann::json idsOf(const Net& net, const std::vector<int>& transitions) {
  nlohmann::json ids = nlohmann::json::array();
  for (int t : transitions) ids.push_back(net.transitions[t].id);
  return ids;
}

nlohmann::json markingJson(const Net& net, const Marking& marking) {
  nlohmann::json tokens = nlohmann::json::object();
  for (size_t p = 0; p < marking.size(); ++p)
    if (marking[p] != 0) tokens[net.places[p].id] = marking[p];
  return tokens;
}

int largest(const std::vector<int>& tokens) {
  int k = 0;
  for (int n : tokens) k = std::max(k, n);
  return k;
}

void printBoundedness(const Net& net, const NetAnalysis& analysis) {
  if (analysis.unbounded_witness) {
    const auto& w = *analysis.unbounded_witness;
    std::string places;
    for (int p : w.growing_places) places += (places.empty() ? "'" : ", '") + net.places[p].id + "'";
    std::printf("  bounded: NO, %s grow%s without limit\n", places.c_str(), w.growing_places.size() == 1 ? "s" : "");
    const std::vector<int> prefix(w.trace.begin(), w.trace.begin() + static_cast<long>(w.covered_after));
    const std::vector<int> loop(w.trace.begin() + static_cast<long>(w.covered_after), w.trace.end());
    std::printf("      %s, then %s, reaches %s, which covers %s: the second part repeats for ever\n",
                prefix.empty() ? "from the initial marking" : ("firing " + traceText(net, prefix)).c_str(),
                traceText(net, loop).c_str(), describeMarking(net, w.covering).c_str(),
                describeMarking(net, w.covered).c_str());
  } else if (!analysis.bounded) {
    std::printf("  bounded: unknown (search and coverability graph incomplete; at most %d tokens in a place so far)\n",
                largest(analysis.max_tokens));
  } else if (const auto k = analysis.bound()) {
    std::printf("  bounded: yes, at most %d token%s in a place (%s)\n", *k, *k == 1 ? "" : "s",
                *k <= 1 ? "1-safe" : (std::to_string(*k) + "-safe").c_str());
  } else {
    std::printf("  bounded: NO\n");
  }
  if (!analysis.place_bounds) return;
  std::string places;
  for (size_t p = 0; p < net.places.size(); ++p) {
    const auto& b = (*analysis.place_bounds)[p];
    if (!b || *b > 1) places += (places.empty() ? "" : ", ") + net.places[p].id + " " + (b ? std::to_string(*b) : "unbounded");
  }
  if (!places.empty()) std::printf("      places above 1: %s\n", places.c_str());
  if (analysis.coverability_nodes > 0)
    std::printf("      (bounds from the coverability graph, %zu nodes)\n", analysis.coverability_nodes);
}

}  // namespace

std::string traceText(const Net& net, const std::vector<int>& trace) {
  std::string text;
  const size_t n = trace.size();
  for (size_t i = 0; i < n; ++i) {
    if (n > kTraceHead + kTraceTail && i == kTraceHead) {
      text += ", ... " + std::to_string(n - kTraceHead - kTraceTail) + " more ...";
      i = n - kTraceTail - 1;
      continue;
    }
    text += (text.empty() ? "" : ", ") + net.transitions[trace[i]].id;
  }
  return text.empty() ? "(nothing)" : text;
}

void printAnalysis(const Net& net, const NetAnalysis& analysis, const NetAnalysisOptions& options) {
  std::printf("P/T net analysis (standard firing rule):\n");
  std::printf("  markings: %zu reachable%s\n", analysis.markings,
              analysis.complete           ? ", all explored"
              : analysis.unbounded_witness ? " explored; the net is unbounded, so the search is incomplete"
                                           : (" explored; INCOMPLETE: stopped at --max-markings " +
                                              std::to_string(options.max_markings))
                                                 .c_str());
  printBoundedness(net, analysis);
  std::printf("  1-safe: %s\n", yesNoUnknown(analysis.safe()));
  if (analysis.deadlock.value_or(false)) {
    std::printf("  deadlock: YES, %s reached by %s%s\n", describeMarking(net, analysis.deadlock_marking).c_str(),
                analysis.deadlock_trace.empty() ? "(the initial marking)"
                                                : traceText(net, analysis.deadlock_trace).c_str(),
                analysis.deadlock_by_random_walk ? " (found by a random walk past the search: maybe not the shortest)"
                                                 : "");
  } else {
    std::printf("  deadlock: %s\n", analysis.deadlock ? "none" : "unknown (none found in the part explored)");
  }
  if (const auto& dead = analysis.dead_transitions) {
    std::printf("  dead transitions: %s\n", dead->empty() ? "none" : traceText(net, *dead).c_str());
  } else {
    size_t unfired = 0;
    for (bool fired : analysis.fired) unfired += fired ? 0 : 1;
    std::printf("  dead transitions: unknown; %zu not fired in the part explored\n", unfired);
  }
  std::printf("  initial marking reachable again from every marking (reversible): %s\n",
              yesNoUnknown(analysis.reversible));
}

nlohmann::json analysisJson(const Net& net, const NetAnalysis& analysis) {
  nlohmann::json json;
  json["net"] = net.id;
  json["file"] = net.file;
  json["places"] = net.places.size();
  json["transitions"] = net.transitions.size();
  json["arcs"] = net.arcCount();
  json["markings"] = analysis.markings;
  json["complete"] = analysis.complete;
  json["bounded"] = orNull(analysis.bounded);
  // k of k-safe when bounded; null when unbounded or unknown (then
  // max_tokens_seen says how far the search got).
  json["max_tokens"] = orNull(analysis.bound());
  json["max_tokens_seen"] = largest(analysis.max_tokens);
  nlohmann::json per_place = nlohmann::json::object();
  for (size_t p = 0; p < net.places.size(); ++p)
    per_place[net.places[p].id] =
        analysis.place_bounds ? orNull((*analysis.place_bounds)[p]) : nlohmann::json(nullptr);
  json["max_tokens_per_place"] = per_place;
  json["safe"] = orNull(analysis.safe());
  json["deadlock"] = orNull(analysis.deadlock);
  json["deadlock_trace"] = analysis.deadlock.value_or(false) ? idsOf(net, analysis.deadlock_trace) : nlohmann::json(nullptr);
  if (analysis.deadlock.value_or(false)) {
    json["deadlock_marking"] = markingJson(net, analysis.deadlock_marking);
    json["deadlock_trace_shortest"] = !analysis.deadlock_by_random_walk;
  }
  const auto& dead = analysis.dead_transitions;
  json["dead_transitions"] = dead ? idsOf(net, *dead) : nlohmann::json(nullptr);
  if (!dead) {
    std::vector<int> unfired;
    for (size_t t = 0; t < analysis.fired.size(); ++t)
      if (!analysis.fired[t]) unfired.push_back(static_cast<int>(t));
    json["not_fired_so_far"] = idsOf(net, unfired);
  }
  json["reversible"] = orNull(analysis.reversible);
  if (analysis.unbounded_witness) {
    const auto& w = *analysis.unbounded_witness;
    nlohmann::json witness;
    witness["trace"] = idsOf(net, w.trace);
    witness["repeat_from_step"] = w.covered_after;
    witness["covered"] = markingJson(net, w.covered);
    witness["covering"] = markingJson(net, w.covering);
    nlohmann::json growing = nlohmann::json::array();
    for (int p : w.growing_places) growing.push_back(net.places[p].id);
    witness["growing_places"] = growing;
    json["unbounded_witness"] = witness;
  }
  json["warnings"] = net.warnings;
  return json;
}

}  // namespace beft::net_check
