// beft-bench-planners: every planner on the same queries (MovingAI maps, the
// testbed's scenarios, synthetic traps); prints a table and the targets,
// writes runs.csv, summary.csv, a plot and OMPL benchmark logs.
#include "lib/common/command_line.hpp"
#include "planners/bench/bench_datasets.hpp"
#include "planners/bench/bench_report.hpp"
#include "planners/bench/bench_stats.hpp"
#include "planners/ompl_planner.hpp"
#include "planners/ompl_potential_field.hpp"
#include "planners/ompl_space.hpp"
#include "planners/path_tools.hpp"
#include "planners/planner_factory.hpp"
#include "planners/render.hpp"

#include <CLI/CLI.hpp>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/tools/benchmark/Benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>

namespace bp = beft::planners;
namespace bench = beft::planners::bench;
namespace fs = std::filesystem;

namespace {

constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

struct Options {
  bool quick = false;
  std::string movingai_dir = BEFT_MOVINGAI_DIR;
  std::string scenario_dir = BEFT_SCENARIO_DIR;
  std::string out_dir = "logs/bench-planners";
  std::vector<std::string> planners = bp::benchmarkPlannerNames();
  std::vector<std::string> datasets = {"movingai", "scenario", "trap"};
  int queries = 8;
  int seeds = 3;
  double budget = 1.0;
  double anytime_budget = 0.5;
  double race_cap = 2.0;
  int ompl_runs = 10;
  uint64_t seed = 1;
  std::vector<std::string> pf_params;
};

bool isRandomised(const std::string& planner) { return planner != "astar"; }

void progress(const std::string& text) { std::cerr << "[bench] " << text << std::endl; }

bench::RunRecord runOnce(bp::Planner& planner, const bench::BenchMap& map, const bench::BenchQuery& query,
                         uint64_t seed, double budget) {
  planner.setSeed(seed);
  const bp::PlanResult result = planner.solve(query.start, query.goal, bp::Deadline::after(budget));
  bench::RunRecord r;
  r.planner = planner.name();
  r.dataset = map.dataset;
  r.map = map.name;
  r.query = query.label;
  r.map_width = map.map->width();
  r.map_height = map.map->height();
  r.seed = seed;
  r.success = result.success;
  r.time_ms = 1000.0 * result.planning_time_s;
  r.setup_ms = planner.statistics().count("setup_ms") ? planner.statistics().at("setup_ms") : 0.0;
  r.optimum = query.optimum;
  r.message = result.message;
  if (result.success) {
    r.length = result.length();
    r.ratio = query.optimum > 0 ? r.length / query.optimum : 1.0;
    r.turning_deg = bp::totalTurning(result.path) * kRadToDeg;
    r.clearance = bp::minClearance(*map.map, result.path);
    r.waypoints = static_cast<int>(result.path.size());
  }
  return r;
}

// RRTConnect (with simplification, and the shared tightening if enabled), restarted until
// its best path is no longer than `target_length`: the time that took, or
// +infinity when `cap` seconds were not enough.
double timeToMatchLength(bp::Planner& rrt, const bench::BenchQuery& query, double target_length, double cap) {
  double spent = 0;
  while (spent < cap) {
    const bp::PlanResult r = rrt.solve(query.start, query.goal, bp::Deadline::after(cap - spent));
    spent += r.planning_time_s;
    if (r.success && r.length() <= target_length + 1e-9) return 1000.0 * spent;
  }
  return std::numeric_limits<double>::infinity();
}

// OMPL's own benchmark on one query: the potential-field planners as
// ompl::base::Planner beside OMPL's planners; writes OMPL's log format.
void omplBenchmark(const bench::BenchMap& map, const bench::BenchQuery& query, const Options& options,
                   const std::string& file) {
  namespace ob = ompl::base;
  namespace og = ompl::geometric;
  const auto si = bp::makeSpaceInformation(map.map);
  og::SimpleSetup setup(si);
  ob::ScopedState<> start(si), goal(si);
  bp::setState(start.get(), query.start);
  bp::setState(goal.get(), query.goal);
  setup.setStartAndGoalStates(start, goal, 1e-6);
  setup.setOptimizationObjective(std::make_shared<ob::PathLengthOptimizationObjective>(si));
  ompl::tools::Benchmark benchmark(setup, map.name + "_" + query.label);
  bp::PotentialFieldParams geodesic;
  geodesic.target = bp::TargetPotential::Geodesic;
  benchmark.addPlanner(std::make_shared<bp::PotentialFieldOmplPlanner>(si, map.map, bp::PotentialFieldParams{}, options.seed));
  benchmark.addPlanner(std::make_shared<bp::PotentialFieldOmplPlanner>(si, map.map, geodesic, options.seed));
  for (const char* name : {"RRTConnect", "RRTstar", "InformedRRTstar", "BITstar", "PRMstar"}) {
    benchmark.addPlanner(bp::allocateOmplPlanner(name, si));
  }
  ompl::tools::Benchmark::Request request(options.budget, 4096.0, static_cast<unsigned>(options.ompl_runs));
  request.displayProgress = false;
  request.saveConsoleOutput = false;
  request.simplify = true;
  benchmark.benchmark(request);
  if (!benchmark.saveResultsToFile(file.c_str())) throw std::runtime_error(file + ": cannot write");
}

std::string joined(const std::vector<std::string>& items, const std::string& separator = ", ") {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : separator) + item;
  return out;
}

std::string formatMs(double ms) {
  if (std::isinf(ms)) return "not reached";
  char text[32];
  std::snprintf(text, sizeof text, "%.2f ms", ms);
  return text;
}

// The command line; an exit code when the program should end here.
std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app{
      "Benchmarks every planner on the same queries: the MovingAI maps and scenario files (a stratified sample of "
      "reachable queries per map, point robot), obstacle maps of the testbed's scenarios (robot radius inflation) "
      "and synthetic traps (U-shaped obstacle facing the start, narrow gap, comb). Per planner and map: success "
      "rate, path length relative to the octile optimum, planning time (median and quartiles), smoothness "
      "(total turning) and clearance. Randomised planners run over several seeds. Writes runs.csv, summary.csv, "
      "length_vs_time.png and OMPL benchmark logs (ompl_*.log) to --out, prints the table and the targets."};
  bool quick = false;
  app.add_flag("--quick", quick,
               "a run of about a minute: 2 queries per map, 2 seeds, 0.1 s for anytime planners, 3 OMPL runs");
  app.add_option("--movingai", o.movingai_dir, "folder of MovingAI .map + .map.scen files")->capture_default_str();
  app.add_option("--scenarios", o.scenario_dir, "folder of scenario .xml files")->capture_default_str();
  app.add_option("--out", o.out_dir, "output folder")->capture_default_str();
  app.add_option("--planners", o.planners, "planners to compare: " + joined(bp::plannerNames()))
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--datasets", o.datasets, "movingai, scenario, trap")->delimiter(',')->capture_default_str();
  auto* queries_opt = app.add_option("--queries", o.queries, "queries per map")->check(CLI::Range(1, 1000))->capture_default_str();
  auto* seeds_opt = app.add_option("--seeds", o.seeds, "runs of each randomised planner per query")->check(CLI::Range(1, 1000))->capture_default_str();
  app.add_option("--budget", o.budget, "planning deadline per run [s]")->check(CLI::PositiveNumber)->capture_default_str();
  auto* anytime_opt = app.add_option("--anytime-budget", o.anytime_budget,
                                     "deadline of asymptotically optimal planners, which use all of it [s]")
                          ->check(CLI::PositiveNumber)
                          ->capture_default_str();
  auto* race_opt = app.add_option("--race-cap", o.race_cap, "RRTConnect restarts stop after this long [s]")
                       ->check(CLI::PositiveNumber)
                       ->capture_default_str();
  auto* runs_opt = app.add_option("--ompl-runs", o.ompl_runs, "runs per planner in the OMPL benchmark logs (0: none)")
                       ->check(CLI::Range(0, 10000))
                       ->capture_default_str();
  app.add_option("--seed", o.seed, "first seed")->capture_default_str();
  app.add_option("--param", o.pf_params, "potential-field parameter name=value, repeatable: " +
                                            joined(bp::PotentialFieldParams::names()));
  if (const auto code = beft::parseCommandLine(app, argc, argv)) return code;
  o.quick = quick;
  if (quick) {
    if (queries_opt->count() == 0) o.queries = 2;
    if (seeds_opt->count() == 0) o.seeds = 2;
    if (anytime_opt->count() == 0) o.anytime_budget = 0.1;
    if (race_opt->count() == 0) o.race_cap = 0.5;
    if (runs_opt->count() == 0) o.ompl_runs = 3;
  }
  return std::nullopt;
}

// The planners asked for; false (and a message) on a bad name or dataset.
bool makePlanners(const Options& o, std::vector<std::unique_ptr<bp::Planner>>& planners) {
  try {
    bp::seedOmpl(o.seed);
    bp::PlannerConfig config;
    config.seed = o.seed;
    for (const auto& p : o.pf_params) config.pf_params.push_back(bp::splitParameter(p));
    for (const auto& name : o.planners) {
      planners.push_back(bp::makePlanner(name, config));
    }
    for (const auto& d : o.datasets) {
      if (d != "movingai" && d != "scenario" && d != "trap") throw std::invalid_argument("unknown dataset '" + d + "'");
    }
    fs::create_directories(o.out_dir);
  } catch (const std::exception& e) {
    std::cerr << "beft-bench-planners: error: " << e.what() << "\n";
    return false;
  }
  return true;
}

std::vector<bench::BenchMap> loadMaps(const Options& o) {
  const auto wants = [&o](const std::string& dataset) {
    return std::find(o.datasets.begin(), o.datasets.end(), dataset) != o.datasets.end();
  };

  std::vector<std::string> notes;
  std::vector<bench::BenchMap> maps;
  if (wants("movingai")) for (auto& m : bench::movingAiMaps(o.movingai_dir, o.queries, notes)) maps.push_back(std::move(m));
  if (wants("scenario")) for (auto& m : bench::scenarioMaps(o.scenario_dir, o.queries, o.seed, notes)) maps.push_back(std::move(m));
  if (wants("trap")) for (auto& m : bench::trapMaps()) maps.push_back(std::move(m));
  for (const auto& note : notes) progress(note);

  return maps;
}

std::vector<bench::RunRecord> runAll(const Options& o, const std::vector<bench::BenchMap>& maps,
                                     std::vector<std::unique_ptr<bp::Planner>>& planners) {
  std::vector<bench::RunRecord> runs;
  for (const bench::BenchMap& map : maps) {
    progress(map.dataset + " " + map.name + " (" + std::to_string(map.map->width()) + " x " +
             std::to_string(map.map->height()) + "): " + std::to_string(map.queries.size()) + " queries");
    for (auto& planner : planners) {
      planner->setup(map.map);
      for (const bench::BenchQuery& query : map.queries) {
        const int seeds = isRandomised(planner->name()) ? o.seeds : 1;
        const double budget = planner->isAnytime() ? o.anytime_budget : o.budget;
        for (int s = 0; s < seeds; ++s) runs.push_back(runOnce(*planner, map, query, o.seed + s, budget));
      }
    }
  }

  return runs;
}

struct Outputs {
  std::string runs_csv, summary_csv, plot_png;
};

// Prints the tables, writes runs.csv, summary.csv and the plot; false (and
// a message) when a file cannot be written.
bool writeTables(const Options& o, const std::vector<bench::RunRecord>& runs,
                 const std::vector<std::string>& planner_names, Outputs& files) {
  // Tables, CSV, plot.
  const auto per_map = bench::summarize(runs, true);
  const auto overall = bench::summarize(runs, false);
  std::cout << "\nPer planner and map (" << runs.size() << " runs; deadline " << o.budget << " s, anytime planners "
            << o.anytime_budget << " s; " << o.seeds << " seeds for randomised planners; lengths in cells after the "
            << "shared tightening, relative to the octile optimum):\n";
  bench::printTable(std::cout, per_map);
  std::cout << "\nAll maps:\n";
  bench::printTable(std::cout, overall);

  std::vector<bench::Summary> all_rows = per_map;
  all_rows.insert(all_rows.end(), overall.begin(), overall.end());
  files.runs_csv = (fs::path(o.out_dir) / "runs.csv").string();
  files.summary_csv = (fs::path(o.out_dir) / "summary.csv").string();
  files.plot_png = (fs::path(o.out_dir) / "length_vs_time.png").string();
  try {
    bench::writeRunsCsv(files.runs_csv, runs);
    bench::writeSummaryCsv(files.summary_csv, all_rows);
    bp::writePng(files.plot_png, bench::plotLengthRatioVsTime(runs, planner_names,
                                                        o.quick ? "beft bench planners --quick" : "beft bench planners"));
  } catch (const std::exception& e) {
    std::cerr << "beft-bench-planners: error: " << e.what() << "\n";
    return false;
  }

  return true;
}

// RRTConnect with OMPL's path simplification as OMPL users run it, and the
// same followed by the shared tightening every planner gets here, restarted
// until as short as pf-geodesic's path on the 256 x 256 maps.
void raceRrtConnect(const Options& o, const std::vector<bench::BenchMap>& maps,
                    const std::vector<bench::RunRecord>& runs) {
  bp::PlannerConfig config;
  config.seed = o.seed;
  auto rrt_simplified = bp::makePlanner("ompl:RRTConnect", config);
  rrt_simplified->setTighten(false);
  auto rrt_tightened = bp::makePlanner("ompl:RRTConnect", config);
  std::vector<double> pf_times, simplified_times, tightened_times;
  for (const bench::BenchMap& map : maps) {
    if (map.dataset != "movingai" || map.map->width() != 256 || map.map->height() != 256) continue;
    rrt_simplified->setup(map.map);
    rrt_tightened->setup(map.map);
    for (const bench::BenchQuery& query : map.queries) {
      for (const auto& r : runs) {
        if (r.planner != "pf-geodesic" || r.map != map.name || r.query != query.label || !r.success) continue;
        pf_times.push_back(r.time_ms);
        simplified_times.push_back(timeToMatchLength(*rrt_simplified, query, r.length, o.race_cap));
        tightened_times.push_back(timeToMatchLength(*rrt_tightened, query, r.length, o.race_cap));
      }
    }
  }
  if (!pf_times.empty()) {
    const double pf_median = bench::median(pf_times);
    const auto reached = [](const std::vector<double>& times) {
      return std::count_if(times.begin(), times.end(), [](double t) { return std::isfinite(t); });
    };
    const double simplified_median = bench::median(simplified_times);  // +inf sorts last
    const double tightened_median = bench::median(tightened_times);
    std::printf("  256 x 256 maps, %zu pf-geodesic runs: median planning time %s\n", pf_times.size(),
                formatMs(pf_median).c_str());
    std::printf("    RRTConnect + OMPL simplification, restarted until as short (cap %.1f s): median %s "
                "(reached in %ld of %zu); target %s\n",
                o.race_cap, formatMs(simplified_median).c_str(), reached(simplified_times), simplified_times.size(),
                pf_median < simplified_median ? "met" : "NOT met");
    std::printf("    the same + the shared tightening: median %s (reached in %ld of %zu)%s\n",
                formatMs(tightened_median).c_str(), reached(tightened_times), tightened_times.size(),
                pf_median < tightened_median ? "" : ": faster than pf-geodesic");
  }
}

// The paper's planner: its success rate and where it fails.
void reportPaperPlanner(const bench::Summary& p, const std::vector<bench::RunRecord>& runs) {
  std::printf("  pf (the paper's planner) success rate: %.1f%% (%d of %d runs); median length ratio %.3f\n",
              100.0 * p.success_rate, p.successes, p.runs, p.ratio_median);
  struct Failures {
    int failed = 0, runs = 0;
    std::string example;
  };
  std::map<std::string, Failures> by_map;
  for (const auto& r : runs) {
    if (r.planner != "pf") continue;
    Failures& entry = by_map[r.dataset + " " + r.map];
    ++entry.runs;
    if (r.success) continue;
    ++entry.failed;
    if (entry.example.empty()) entry.example = r.query + ": " + r.message;
  }
  for (const auto& [name, f] : by_map) {
    if (f.failed > 0) {
      std::printf("    fails on %-24s %d of %d runs, e.g. %s\n", name.c_str(), f.failed, f.runs, f.example.c_str());
    }
  }
}

// OMPL's benchmark tooling on a few problems; the log files written.
std::vector<std::string> writeOmplLogs(const Options& o, const std::vector<bench::BenchMap>& maps) {
  std::vector<std::string> logs;
  if (o.ompl_runs > 0) {
    std::set<std::string> chosen = o.quick ? std::set<std::string>{"u-trap"}
                                           : std::set<std::string>{"u-trap", "comb", "narrow-gap", "Berlin_0_256",
                                                                   "Boston_2_512", "maze512-32-9", "yard"};
    for (const bench::BenchMap& map : maps) {
      if (!chosen.count(map.name) || map.queries.empty()) continue;
      const std::string file = (fs::path(o.out_dir) / ("ompl_" + map.name + ".log")).string();
      progress("OMPL benchmark on " + map.name + " (" + std::to_string(o.ompl_runs) + " runs per planner)");
      try {
        omplBenchmark(map, map.queries.back(), o, file);
        logs.push_back(file);
      } catch (const std::exception& e) {
        progress(std::string("OMPL benchmark failed: ") + e.what());
      }
    }
  }

  return logs;
}

void printTargets(const Options& o, const std::vector<bench::BenchMap>& maps,
                  const std::vector<bench::RunRecord>& runs) {
  const auto overall = bench::summarize(runs, false);
  std::cout << "\nTargets:\n";
  const auto summary_of = [&overall](const std::string& name) -> const bench::Summary* {
    for (const auto& s : overall) if (s.planner == name) return &s;
    return nullptr;
  };
  if (const auto* g = summary_of("pf-geodesic")) {
    std::printf("  pf-geodesic succeeds on every reachable query: %s (%d of %d runs)\n",
                g->successes == g->runs ? "yes" : "NO", g->successes, g->runs);
    std::printf("  pf-geodesic median length within 3%% of the octile optimum: %s (median ratio %.4f)\n",
                g->ratio_median <= 1.03 ? "yes" : "NO", g->ratio_median);
  }
  if (summary_of("pf-geodesic") != nullptr) raceRrtConnect(o, maps, runs);
  if (const auto* p = summary_of("pf")) reportPaperPlanner(*p, runs);
}
}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (const auto code = parseOptions(argc, argv, o)) return *code;
  std::vector<std::unique_ptr<bp::Planner>> planners;
  if (!makePlanners(o, planners)) return 2;
  const auto begin = std::chrono::steady_clock::now();
  const std::vector<bench::BenchMap> maps = loadMaps(o);
  if (maps.empty()) {
    std::cerr << "beft-bench-planners: error: no maps to run on\n";
    return 2;
  }
  const std::vector<bench::RunRecord> runs = runAll(o, maps, planners);
  std::vector<std::string> planner_names;
  for (const auto& p : planners) planner_names.push_back(p->name());
  Outputs files;
  if (!writeTables(o, runs, planner_names, files)) return 1;
  printTargets(o, maps, runs);
  const std::vector<std::string> logs = writeOmplLogs(o, maps);
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  std::cout << "\nWrote " << files.runs_csv << ", " << files.summary_csv << ", " << files.plot_png;
  for (const auto& log : logs) std::cout << ", " << log;
  std::printf("\n(%.0f s; OMPL logs load into Planner Arena or ompl_benchmark_statistics.py)\n", elapsed);
  return 0;
}
