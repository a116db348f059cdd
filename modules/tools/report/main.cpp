// beft-report: the report and pictures of a run, from its LCM log.
#include <iostream>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "lib/common/command_line.hpp"
#include "lib/scenario/load_scenario.hpp"
#include "lib/report/report_files.hpp"
#include "lib/report/report_json.hpp"
#include "lib/report/run_record.hpp"
#include "lib/report/run_scoring.hpp"
#include "tools/report/path_efficiency.hpp"
#include "tools/report/unsettled_reasons.hpp"

namespace {

struct Options {
  std::string log_path, scenario_path, out_dir;
  std::optional<double> wall_time;
  beft::report::ScoringOptions scoring;
  beft::report::PathEfficiencyOptions paths;
  bool quiet = false;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app{
      "beft-report: reads a run's LCM log and writes DIR/report.json (victims found with their position "
      "error, confidence and time, falsified hypotheses, missed persons, path length, collisions, sim and "
      "wall time, ticks per second, path efficiency with --scenario), DIR/map.png (top-down map: ground "
      "truth by category, the robot's obstacle map, its path, the hypotheses) and DIR/weights.png (the "
      "paper's Fig. 4: dynamic weights, "
      "task and viewing direction over time), and prints a summary.\n"
      "A victim is found when a hypothesis ends with best category 'person', confidence at least "
      "--person-confidence, was seen by vision and is not falsified; heard alone is not enough."};
  app.add_option("log", o.log_path, "the run's LCM log (run.lcmlog)")->required();
  app.add_option("--scenario", o.scenario_path,
                 "scenario XML the run used: ground truth for what the log lacks and a name check");
  app.add_option("--out", o.out_dir, "folder for report.json, map.png and weights.png")->required();
  app.add_option("--wall-time", o.wall_time, "wall time of the run as measured by the runner [s]; "
                                             "default: the span of the log's timestamps")
      ->check(CLI::PositiveNumber);
  app.add_option("--person-confidence", o.scoring.person_confidence,
                 "minimum fused confidence of 'person' for a victim [0..1]")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  app.add_option("--match-radius", o.scoring.match_radius,
                 "how far a hypothesis not keyed by a person's id may be from that person to match it [m]")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--planner-inflation", o.paths.inflation_m,
                 "the planner's obstacle inflation, for the shortest paths of path efficiency [m]")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_flag("--quiet", o.quiet, "do not print the summary");
  app.add_flag("--log-incomplete", o.scoring.log_incomplete,
               "the recorder died during the run: the report says the log misses what came after");
  if (const auto code = beft::parseCommandLine(app, argc, argv)) return code;
  o.scoring.wall_time_s = o.wall_time;
  return std::nullopt;
}

// The run's log, with the scenario's ground truth where the log lacks it;
// what is missing or did not decode, said on stderr.
beft::report::RunRecord readRecord(const Options& o, const std::optional<beft::scenario::Scenario>& scenario) {
  auto record = beft::report::readRunLog(o.log_path);
  if (scenario) {
    for (const auto& warning : beft::report::applyScenario(record, *scenario))
      std::cerr << "beft-report: warning: " << warning << "\n";
  } else if (record.truth.empty()) {
    std::cerr << "beft-report: warning: " << o.log_path
              << " has no GT_OBJECTS and no --scenario was given: nothing to score against\n";
  }
  for (const auto& [channel, count] : record.rejected)
    std::cerr << "beft-report: warning: " << count << " message(s) on " << channel << " refused as malformed\n";
  if (record.other_run_messages > 0)
    std::cerr << "beft-report: warning: " << record.other_run_messages
              << " message(s) of another run on the same LCM URL were left out\n";
  for (const auto& [process, refused] : record.process_rejects)
    if (refused.unauthenticated > 0)
      std::cerr << "beft-report: warning: " << process << " refused " << refused.unauthenticated
                << " message(s) without a valid tag of the run's key\n";
  if (!record.log_damage.empty())
    std::cerr << "beft-report: warning: " << o.log_path << ": " << record.log_damage << "\n";
  if (record.robot.empty()) std::cerr << "beft-report: warning: " << o.log_path << " has no ROBOT_STATE\n";
  return record;
}

int report(const Options& o) {
  try {
    std::optional<beft::scenario::Scenario> scenario;
    if (!o.scenario_path.empty()) scenario = beft::scenario::loadScenario(o.scenario_path, nullptr);
    const auto record = readRecord(o, scenario);
    auto report = beft::report::scoreRun(record, o.scoring);
    // Shortest paths need the ground truth's obstacles: the scenario's.
    if (scenario) beft::report::scorePathEfficiency(record, *scenario, o.paths, report);
    if (scenario) beft::report::explainUnsettled(*scenario, report);
    beft::report::writeReportFiles(record, report, o.out_dir);
    if (!o.quiet) beft::report::printSummary(report, std::cout);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "beft-report: error: " << e.what() << "\n";
  }
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const auto code = parseOptions(argc, argv, options)) return *code;
  return report(options);
}
