// beft-run: run the mission on a scenario (./beft run SCENARIO.xml).
#include <CLI/CLI.hpp>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <climits>
#include <cmath>
#include <cstdio>
#include <ctime>

#include "free_port.hpp"
#include "lcm_url.hpp"
#include "load_scenario.hpp"
#include "own_bin_dir.hpp"
#include "supervisor.hpp"

namespace {

std::string absolutePath(const std::string& path) {
  if (!path.empty() && path[0] == '/') return path;
  char cwd[PATH_MAX] = {0};
  if (!getcwd(cwd, sizeof(cwd))) return path;
  return std::string(cwd) + "/" + path;
}

bool makeDirectories(const std::string& path) {
  std::string partial;
  for (std::size_t i = 0; i <= path.size(); ++i) {
    if (i == path.size() || path[i] == '/') {
      if (!partial.empty()) mkdir(partial.c_str(), 0755);
    }
    if (i < path.size()) partial += path[i];
  }
  struct stat info {};
  return stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode);
}

std::string timestamp() {
  const std::time_t now = std::time(nullptr);
  char buffer[32];
  std::strftime(buffer, sizeof(buffer), "%Y%m%d-%H%M%S", std::localtime(&now));
  return buffer;
}

// Runs a program to completion, its output passed through; returns its exit code.
int runProgram(const std::vector<std::string>& args) {
  const pid_t pid = fork();
  if (pid == 0) {
    std::vector<char*> argv;
    for (const auto& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
    argv.push_back(nullptr);
    execvp(argv[0], argv.data());
    std::fprintf(stderr, "cannot execute %s\n", argv[0]);
    _exit(127);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string source_dir = BEFT_SOURCE_DIR;
  std::string scenario_path, out_dir, logs_dir = source_dir + "/logs";
  std::string launch_file = source_dir + "/scenarios/launch/mission.xml";
  std::string net = source_dir + "/scenarios/nets/default.pnml";
  std::string planner = "pf-geodesic";
  std::vector<std::string> except, sets;
  long long seed = -1, max_ticks = -1;
  bool verbose = false, report = true;

  CLI::App app(
      "Runs the mission on a scenario: starts every process on a free LCM port of its own "
      "(world, blackboard, arbiter, experts, task stack, planner), runs in lockstep until the "
      "mission is done or the scenario's duration ends, stops them, and writes the run's "
      "folder: run.lcmlog (lcm-logplayer plays it), processes.log, report.json, map.png, "
      "weights.png. Prints the folder's path last. Exits 0 when the run itself worked, "
      "whatever the mission's outcome.",
      "beft-run");
  app.add_option("scenario", scenario_path, "scenario XML file")->required();
  app.add_option("--out", out_dir, "run folder (default logs/<scenario>-<time>/)");
  app.add_option("--planner", planner, "pf | pf-geodesic | astar | ompl:NAME")->capture_default_str();
  app.add_option("--net", net, "Petri net (PNML) of the schedule");
  app.add_option("--launch", launch_file, "launch file listing the processes");
  app.add_option("--seed", seed, "seed (default: the scenario's)");
  app.add_option("--max-ticks", max_ticks, "stop after this many ticks (default: duration / dt)");
  app.add_option("--except", except, "do not start this process; start it by hand (repeatable)");
  app.add_option("--set", sets, "NAME=VALUE for another <arg> of the launch file");
  app.add_flag("--verbose,-v", verbose, "echo every process's output (always in processes.log)");
  app.add_flag("!--no-report", report, "skip report.json and the pictures");
  CLI11_PARSE(app, argc, argv);

  beft::scenario::Scenario scenario;
  try {
    scenario = beft::scenario::loadScenario(scenario_path);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  if (seed < 0) seed = static_cast<long long>(scenario.seed);
  if (max_ticks < 0) max_ticks = static_cast<long long>(std::ceil(scenario.duration / scenario.dt - 1e-9));

  if (out_dir.empty()) out_dir = logs_dir + "/" + scenario.name + "-" + timestamp();
  out_dir = absolutePath(out_dir);
  if (!makeDirectories(out_dir)) {
    std::fprintf(stderr, "[run] error: cannot create the run folder %s\n", out_dir.c_str());
    return 1;
  }
  const int port = beft::launch::findFreeUdpPort();
  if (port < 0) {
    std::fprintf(stderr, "[run] error: no free UDP port for LCM\n");
    return 1;
  }

  beft::launch::SupervisorOptions options;
  options.lcm_url = beft::lcmUrlForPort(port);
  options.bin_dir = beft::ownBinDir();
  options.except = {except.begin(), except.end()};
  options.record_log = out_dir + "/run.lcmlog";
  options.quiet_children = !verbose;
  options.output_file = out_dir + "/processes.log";

  std::map<std::string, std::string> args = {
      {"scenario", absolutePath(scenario_path)}, {"net", absolutePath(net)},
      {"planner", planner},                      {"seed", std::to_string(seed)},
      {"max_ticks", std::to_string(max_ticks)},  {"dt", std::to_string(scenario.dt)},
      {"lcm_url", options.lcm_url}};
  for (const auto& set : sets) {
    const auto eq = set.find('=');
    if (eq == std::string::npos || eq == 0) {
      std::fprintf(stderr, "[run] error: --set '%s' is not NAME=VALUE\n", set.c_str());
      return 2;
    }
    args[set.substr(0, eq)] = set.substr(eq + 1);
  }

  std::printf("[run] scenario %s (%s): up to %lld ticks of %.3g s, seed %lld, planner %s\n",
              scenario.name.c_str(), scenario_path.c_str(), max_ticks, scenario.dt, seed, planner.c_str());
  std::printf("[run] LCM %s; process output in %s/processes.log\n", options.lcm_url.c_str(), out_dir.c_str());
  std::fflush(stdout);

  beft::launch::RunOutcome outcome;
  const auto start = std::chrono::steady_clock::now();
  try {
    const auto spec = beft::launch::loadLaunchFile(launch_file, args);
    outcome = beft::launch::supervise(spec, options);
  } catch (const beft::launch::LaunchError& e) {
    std::fprintf(stderr, "[run] error: %s\n", e.what());
    return 2;
  }
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const bool worked = outcome.arbiter_ran && outcome.arbiter_exit_code == 0 && !outcome.interrupted;
  std::printf("[run] %s after %.2f s wall time\n", outcome.message.c_str(), wall_s);

  int report_code = 0;
  if (report && outcome.arbiter_ran) {
    char wall[32];
    std::snprintf(wall, sizeof(wall), "%.3f", wall_s);
    report_code = runProgram({options.bin_dir + "/beft-report", options.record_log, "--scenario",
                              absolutePath(scenario_path), "--out", out_dir, "--wall-time", wall});
    if (report_code != 0) std::fprintf(stderr, "[run] error: the report could not be written (code %d)\n", report_code);
  }
  if (!worked)
    std::fprintf(stderr, "[run] error: the run did not complete: %s (see %s/processes.log)\n",
                 outcome.message.c_str(), out_dir.c_str());
  std::printf("%s\n", out_dir.c_str());
  return worked && report_code == 0 ? 0 : 1;
}
