#include "tools/net_check/schedule_report.hpp"

#include <cstdio>
#include <string>

namespace beft::net_check {

using namespace arbiter;

namespace {

constexpr size_t kTraceHead = 24;  // a long trace shows its start and its end
constexpr size_t kTraceTail = 8;

void printTrace(const ReachableState& state) {
  std::string trace;
  const size_t n = state.trace.size();
  for (size_t i = 0; i < n; ++i) {
    if (n > kTraceHead + kTraceTail && i == kTraceHead) {
      trace += ", ... " + std::to_string(n - kTraceHead - kTraceTail) + " more steps ...";
      i = n - kTraceTail - 1;
      continue;
    }
    trace += (trace.empty() ? "" : ", ") + state.trace[i];
  }
  std::printf("      reached by: %s\n", trace.empty() ? "(the initial marking)" : trace.c_str());
}

}  // namespace

void printScheduleSummary(const Net& net, const std::string& path) {
  size_t silent = 0;
  for (const auto& t : net.transitions) silent += t.silent() ? 1 : 0;
  const auto experts = net.experts();
  std::printf("net '%s' (%s): %zu places, %zu transitions: %zu fire an expert, %zu silent\n",
              net.id.c_str(), path.c_str(), net.places.size(), net.transitions.size(),
              net.transitions.size() - silent, silent);
  std::printf("tick transition: %s\n", net.transitions[net.tick_transition].id.c_str());
  std::string list;
  for (const auto& name : experts) {
    std::string level;
    for (const auto& t : net.transitions)
      if (t.expert == name && !t.level.empty()) level = t.level;
    list += (list.empty() ? "" : ", ") + name + (level.empty() ? "" : " (" + level + ")");
  }
  std::printf("experts (%zu): %s\n", experts.size(), list.c_str());
}

namespace {

void printSafety(const Net& net, const ReachabilityReport& report) {
  if (report.unbounded) {
    std::printf("bounded: NO, place '%s' grows without limit: %s covers an earlier marking\n",
                net.places[report.growing_place].id.c_str(),
                describeState(net, *report.unbounded_witness).c_str());
    printTrace(*report.unbounded_witness);
  }
  if (report.unbounded) {
    std::printf("1-safe: NO (unbounded)\n");
  } else if (report.safe) {
    std::printf("1-safe: %s\n", report.complete ? "yes" : "unknown (exploration incomplete)");
  } else {
    std::printf("1-safe: NO\n");
    std::printf("      place '%s' holds %d tokens in: %s\n", net.places[report.unsafe_place].id.c_str(),
                report.unsafe_witness->tokens[report.unsafe_place],
                describeState(net, *report.unsafe_witness).c_str());
    printTrace(*report.unsafe_witness);
  }

}

void printDeadTransitions(const Net& net, const ReachabilityReport& report) {
  if (!report.complete) {
    std::printf("dead transitions: unknown (exploration incomplete); %zu not fired in the part explored\n",
                report.dead_transitions.size());
  } else if (report.dead_transitions.empty()) {
    std::printf("dead transitions: none\n");
  } else {
    std::printf("dead transitions: %zu\n", report.dead_transitions.size());
    for (int t : report.dead_transitions) {
      const Transition& transition = net.transitions[t];
      std::printf("      %s:%d: %s%s can never fire\n", net.file.c_str(), transition.line,
                  transition.id.c_str(),
                  transition.silent() ? "" : (" (" + transition.expert + ")").c_str());
    }
  }

}

void printDeadlocks(const Net& net, const ReachabilityReport& report) {
  if (report.num_deadlocks == 0) {
    std::printf("deadlock markings: none\n");
  } else {
    std::printf("deadlock markings: %zu (nothing enabled, nothing running)\n", report.num_deadlocks);
    for (const auto& state : report.deadlock_witnesses) {
      std::printf("      %s\n", describeState(net, state).c_str());
      printTrace(state);
    }
  }

}

void printTickEnd(const Net& net, const ReachabilityReport& report) {
  if (!report.complete) {
    std::printf("tick end reachable from every reachable marking: unknown (exploration incomplete)\n");
  } else if (report.num_states_without_tick_end == 0) {
    std::printf("tick end reachable from every reachable marking: yes\n");
  } else {
    std::printf("tick end reachable from every reachable marking: NO (%zu markings cannot reach it)\n",
                report.num_states_without_tick_end);
    std::printf("      for example: %s\n", describeState(net, *report.no_tick_end_witness).c_str());
    printTrace(*report.no_tick_end_witness);
  }

}

// The last line and the exit code: 0 when 1-safe and live, 1 with the reasons.
int printVerdict(const ReachabilityReport& report, const ReachabilityOptions& options) {
  if (report.ok()) {
    std::printf("result: OK, 1-safe and live\n");
    return 0;
  }
  std::string reasons;
  const auto add = [&reasons](const std::string& r) { reasons += (reasons.empty() ? "" : "; ") + r; };
  if (report.unbounded) add("unbounded");
  else if (!report.complete) add("exploration incomplete (more than " + std::to_string(options.max_states) + " states)");
  if (!report.safe && !report.unbounded) add("not 1-safe");
  if (report.complete && !report.dead_transitions.empty())
    add(std::to_string(report.dead_transitions.size()) + " dead transition(s)");
  if (report.num_deadlocks > 0) add(std::to_string(report.num_deadlocks) + " deadlock marking(s)");
  if (report.num_states_without_tick_end > 0) add("the tick end is not always reachable");
  std::printf("result: NOT OK: %s\n", reasons.c_str());
  return 1;
}

}  // namespace

int printScheduleChecks(const Net& net, const ReachabilityReport& report, const ReachabilityOptions& options) {
  std::printf("reachable markings: %zu (places and firings in flight; %zu distinct markings of the places)%s\n",
              report.num_states, report.num_place_markings,
              report.complete    ? ""
              : report.unbounded ? " -- exploration stopped: the net is unbounded, results are partial"
                                 : " -- exploration stopped at --max-markings, results are partial");
  printSafety(net, report);
  printDeadTransitions(net, report);
  printDeadlocks(net, report);
  printTickEnd(net, report);
  return printVerdict(report, options);
}

}  // namespace beft::net_check
