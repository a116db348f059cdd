// beft-net-check: analyses any place/transition net in PNML (bounded, k-safe,
// deadlocks with a firing sequence, dead transitions, reversible) and, when
// the net is annotated as an arbiter schedule, whether the arbiter can run it.
// Run as `./beft net check FILE.pnml`.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <optional>
#include <string>

#include "tools/net_check/analysis_report.hpp"
#include "lib/common/command_line.hpp"
#include "lib/petri/net_analysis.hpp"
#include "lib/petri/pnml_reader.hpp"
#include "lib/petri/reachability_graph.hpp"
#include "tools/net_check/schedule_report.hpp"

namespace {

using namespace beft::arbiter;
namespace report = beft::net_check;

struct Options {
  std::string path;
  std::string net_id;
  size_t max_markings = 1000000;
  bool json = false;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app(
      "Analyses a place/transition net in PNML, as written by any editor (ISO PNML, ProM, pm4py,\n"
      "WoPeD, PIPE): its reachable markings under the standard firing rule, whether it is bounded\n"
      "(with a firing sequence that can repeat for ever when not), the most tokens a place holds\n"
      "(k-safe, 1-safe), a reachable deadlock with the shortest firing sequence to it, dead\n"
      "transitions, and whether the initial marking is reachable again from every marking.\n"
      "When the net carries the arbiter's annotations (<toolspecific tool=\"beft\">), the BEFT\n"
      "checks follow: every transition an expert or silent, one tick transition, and, in the\n"
      "arbiter's model (an expert transition is start + end), 1-safe, no dead transition and the\n"
      "tick end reachable from every reachable marking.\n"
      "Exit 0: analysed (and, for a schedule, the arbiter can run it); 1: a schedule the arbiter\n"
      "cannot run (the reasons are printed); 2: the file is not a readable P/T net.",
      "beft-net-check");
  app.add_option("net", o.path, "PNML file")->required();
  app.add_option("--net-id", o.net_id, "the <net> to read when the file holds several (default: the first)");
  app.add_option("--max-markings,--max-states", o.max_markings,
                 "stop the search after this many markings and say what was learned so far")
      ->capture_default_str()
      ->check(CLI::Range(size_t{1}, size_t{200000000}));
  app.add_flag("--json", o.json, "print one JSON object instead of text");
  if (const auto code = beft::parseCommandLine(app, argc, argv)) return code;
  return std::nullopt;
}

struct ScheduleVerdict {
  bool checked = false;  // annotated and free of annotation problems
  ReachabilityReport report;
};

nlohmann::json scheduleJson(const Net& net, const ScheduleVerdict& verdict) {
  if (!net.annotated) return nullptr;
  nlohmann::json json;
  json["problems"] = net.schedule_problems;
  if (verdict.checked) {
    json["states"] = verdict.report.num_states;
    json["complete"] = verdict.report.complete;
    json["safe"] = verdict.report.safe && !verdict.report.unbounded;
    json["live"] = verdict.report.live();
    json["ok"] = verdict.report.ok();
  } else {
    json["ok"] = false;
  }
  return json;
}

int check(const Options& o) {
  PnmlReadOptions read_options;
  read_options.net_id = o.net_id;
  read_options.schedule = false;
  Net net;
  try {
    net = readPnmlFile(o.path, read_options);
  } catch (const NetError& e) {
    for (const auto& problem : e.problems()) std::fprintf(stderr, "%s\n", problem.c_str());
    return 2;
  }
  NetAnalysisOptions analysis_options;
  analysis_options.max_markings = o.max_markings;
  const NetAnalysis analysis = analyseNet(net, analysis_options);

  ReachabilityOptions schedule_options;
  schedule_options.max_states = o.max_markings;
  ScheduleVerdict schedule;
  schedule.checked = net.annotated && net.schedule_problems.empty();
  if (schedule.checked) schedule.report = exploreReachability(net, schedule_options);
  const int exit_code = !net.annotated ? 0 : schedule.checked && schedule.report.ok() ? 0 : 1;

  if (o.json) {
    nlohmann::json json = report::analysisJson(net, analysis);
    json["schedule"] = scheduleJson(net, schedule);
    std::printf("%s\n", json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace).c_str());
    return exit_code;
  }
  std::printf("net '%s' (%s): %zu places, %zu transitions, %zu arcs\n", net.id.c_str(), o.path.c_str(),
              net.places.size(), net.transitions.size(), net.arcCount());
  for (const auto& warning : net.warnings) std::printf("warning: %s\n", warning.c_str());
  report::printAnalysis(net, analysis, analysis_options);
  if (!net.annotated) {
    std::printf("BEFT schedule: not annotated (no <toolspecific tool=\"beft\">); `./beft net annotate` makes one\n");
    return exit_code;
  }
  std::printf("BEFT schedule checks (an expert transition is start + end; an expert runs one firing at a time):\n");
  if (!schedule.checked) {
    for (const auto& problem : net.schedule_problems) std::printf("  %s\n", problem.c_str());
    std::printf("result: NOT OK: %zu problem(s) with the annotations\n", net.schedule_problems.size());
    return exit_code;
  }
  report::printScheduleSummary(net, o.path);
  report::printScheduleChecks(net, schedule.report, schedule_options);
  return exit_code;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const auto code = parseOptions(argc, argv, options)) return *code;
  return check(options);
}
