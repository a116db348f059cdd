// beft-run: run the mission on a scenario (./beft run SCENARIO.xml).
#include <CLI/CLI.hpp>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <climits>
#include <cmath>
#include <algorithm>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "lib/launch/camera_sampling.hpp"
#include "lib/common/command_line.hpp"
#include "lib/launch/free_port.hpp"
#include "lib/launch/launch_file.hpp"
#include "lib/launch/launch_identity.hpp"
#include "lib/common/lcm_url.hpp"
#include "lib/scenario/load_scenario.hpp"
#include "lib/common/own_bin_dir.hpp"
#include "lib/launch/run_key.hpp"
#include "lib/launch/run_parameters.hpp"
#include "lib/launch/supervisor.hpp"
#include "lib/launch/tcp_port.hpp"

namespace {

std::string absolutePath(const std::string& path) {
  if (!path.empty() && path[0] == '/') return path;
  char cwd[PATH_MAX] = {0};
  if (!getcwd(cwd, sizeof(cwd))) return path;
  return std::string(cwd) + "/" + path;
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

struct Options {
  std::string scenario_path, out_dir;
  std::string launch_file = std::string(BEFT_SOURCE_DIR) + "/scenarios/launch/mission.xml";
  std::string net;  // default: nets/default.pnml, or nets/binaural.pnml with --acoustics binaural
  std::string acoustics = "ground_truth";
  std::string planner = "pf-geodesic";
  std::vector<std::string> except, sets, kills;
  std::string run_id, key_file;
  std::string record_camera = "all";
  long long seed = -1, max_ticks = -1;  // -1: the scenario's seed, duration / dt
  bool verbose = false, report = true, ssr = false;
  bool real_time = false, fast = false;  // --real-time, --fast
  bool watched = false;                  // someone watches the run live (a viewer): real time unless --fast
  bool view = false;                     // --view: start beft-bridge, the viewer's server
  int view_port = 8765;                  // its TCP port (0: a free one)
  std::vector<std::string> externals;    // --external NAME=COMMAND: that expert's process replaced
};

// Whether the arbiter paces the ticks in real time: asked for, or someone
// watches; --fast always wins (a watched run as fast as it goes).
bool realTimePace(const Options& o) { return !o.fast && (o.real_time || o.watched); }

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app(
      "Runs the mission on a scenario: starts every process on a free LCM port of its own "
      "(world, blackboard, arbiter, experts, task stack, planner), runs in lockstep until the "
      "mission is done or the scenario's duration ends, stops them, and writes the run's "
      "folder: run.lcmlog (lcm-logplayer plays it), processes.log, report.json, map.png, "
      "weights.png. Prints the folder's path last. Exits 0 when the run itself worked, "
      "whatever the mission's outcome.",
      "beft-run");
  app.add_option("scenario", o.scenario_path, "scenario XML file")->required();
  app.add_option("--out", o.out_dir, "run folder (default logs/<scenario>-<time>/)");
  app.add_option("--planner", o.planner, "pf | pf-geodesic | astar | ompl:NAME")->capture_default_str();
  app.add_option("--net", o.net,
                 "Petri net (PNML) of the schedule (default: scenarios/nets/default.pnml; binaural.pnml, which "
                 "fires the ears before audio, with --acoustics binaural)");
  app.add_option("--acoustics", o.acoustics,
                 "where the audio expert's position estimates come from: ground_truth (the paper's experiments: "
                 "true positions degraded by its formulas) or binaural (the ears process renders what the head "
                 "hears with KEMAR impulse responses and the audio expert localises it)")
      ->capture_default_str()
      ->check(CLI::IsMember({"ground_truth", "binaural"}));
  app.add_option("--launch", o.launch_file, "launch file listing the processes");
  app.add_option("--seed", o.seed, "seed (default: the scenario's)");
  app.add_option("--max-ticks", o.max_ticks, "stop after this many ticks (default: duration / dt)");
  app.add_option("--except", o.except, "do not start this process; start it by hand (repeatable)");
  app.add_option("--set", o.sets, "NAME=VALUE for another <arg> of the launch file");
  app.add_option("--run-id", o.run_id,
                 "the run's id (hex), stamped on every message (default: a fresh random one, so that no other "
                 "run's messages, a replayed log's included, are taken for this run's; beft diff and the "
                 "digests leave the id out); another run on the same LCM URL is refused");
  app.add_option("--key", o.key_file,
                 "the run's key (./beft key new FILE; default: BEFT_KEY_FILE): every process tags its messages with "
                 "it and refuses those without a valid tag (another program's, a replayed log's); report.json "
                 "counts what each process refused")
      ->check(CLI::ExistingFile);
  app.add_option("--kill", o.kills,
                 "NAME@TICK: SIGKILL this process once the run reaches the tick, to see it restarted and resume "
                 "from the run's log (fault injection; repeatable)");
  app.add_option("--record-camera", o.record_camera,
                 "camera frames kept in run.lcmlog: all, none, or every:N (those of ticks 0, N, 2N, ...); the "
                 "live processes get every frame. A log without all of them cannot replay the vision expert "
                 "(beft-replay says so), and a vision expert restarted mid-run resumes without the frames left out")
      ->capture_default_str()
      ->check(beft::record::CameraSampling::problemWith);
  app.add_flag("--ssr", o.ssr,
               "also start beft-ssr-bridge: hear the run in a running SoundScape Renderer (ssr-binaural "
               "--ip-server; --set ssr_server_host=HOST --set ssr_port=PORT if it is not at localhost:4711)");
  auto* real_time = app.add_flag("--real-time", o.real_time,
                                 "start each tick no sooner than its simulated time has passed on the wall clock "
                                 "(the arbiter's --pace real-time), to watch the run; what it computes is the same");
  app.add_flag("--fast", o.fast, "each tick as soon as the last has ended (the default, also when the run is watched)")
      ->excludes(real_time);
  app.add_flag("--view", o.view,
               "also start beft-bridge: watch the run in a web browser at the URL it prints (or in Foxglove, "
               "ws://127.0.0.1:PORT), pause, step and send the robot somewhere; the run is paced in real time "
               "unless --fast");
  app.add_option("--port", o.view_port, "with --view: the viewer's TCP port on 127.0.0.1 (0: a free one)")
      ->capture_default_str()
      ->check(CLI::Range(0, 65535));
  app.add_option("--external", o.externals,
                 "NAME=COMMAND: run this command instead of expert NAME's process, an expert written in another "
                 "language that takes part through the run's bridge (modules/python/README.md), e.g. "
                 "dw=\"python3 modules/python/examples/dw_expert.py\"; started, supervised and restarted as NAME's "
                 "process, with --url of the bridge (started too) and --name NAME (repeatable)");
  app.add_flag("--verbose,-v", o.verbose, "echo every process's output (always in processes.log)");
  app.add_flag("!--no-report", o.report, "skip report.json and the pictures");
  if (const auto code = beft::parseCommandLine(app, argc, argv)) return code;
  o.watched = o.watched || o.view;
  // External experts need the bridge, not a viewer: on a free port unless given.
  if (!o.externals.empty() && !o.view && app.count("--port") == 0) o.view_port = 0;
  return std::nullopt;
}

// The launch file's arguments: the run's own, then every --set.
std::map<std::string, std::string> launchArguments(const Options& o, const beft::scenario::Scenario& scenario,
                                                   const std::string& lcm_url) {
  const bool binaural = o.acoustics == "binaural";
  const std::string net = !o.net.empty() ? o.net
                          : std::string(BEFT_SOURCE_DIR) + (binaural ? "/scenarios/nets/binaural.pnml"
                                                                     : "/scenarios/nets/default.pnml");
  std::map<std::string, std::string> args = {
      {"scenario", absolutePath(o.scenario_path)}, {"net", absolutePath(net)},
      {"planner", o.planner},                      {"seed", std::to_string(o.seed)},
      {"max_ticks", std::to_string(o.max_ticks)},  {"dt", std::to_string(scenario.dt)},
      {"lcm_url", lcm_url}};
  if (binaural) {  // only then: a launch file of the user's need not declare them
    args["acoustics"] = o.acoustics;
    args["ears"] = "1";
  }
  if (o.ssr) args["ssr"] = "1";
  if (o.view || !o.externals.empty()) {  // only then: a launch file of the user's need not declare them
    args["view"] = "1";
    args["view_port"] = std::to_string(o.view_port);
    args["view_log"] = o.out_dir + "/processes.log";
  }
  if (realTimePace(o)) args["pace"] = "real-time";  // only then: a launch file of the user's need not declare it
  for (const auto& [name, value] : beft::launch::parseSettings(o.sets)) args[name] = value;
  return args;
}

// --external NAME=COMMAND: the process NAME runs COMMAND (split at spaces;
// a word naming a file here made absolute) and connects to the run's bridge.
void useExternalExperts(const Options& o, beft::launch::LaunchSpec& spec) {
  for (const auto& [name, command] : beft::launch::parseSettings(o.externals)) {
    auto process = std::find_if(spec.processes.begin(), spec.processes.end(),
                                [&name = name](const beft::launch::ProcessSpec& p) { return p.name == name; });
    if (process == spec.processes.end())
      throw beft::launch::LaunchError("--external " + name + ": the launch file starts no process " + name);
    std::vector<std::string> words;
    std::istringstream split(command);
    for (std::string word; split >> word;)
      words.push_back(std::filesystem::exists(word) ? absolutePath(word) : word);
    if (words.empty()) throw beft::launch::LaunchError("--external " + name + ": no command");
    process->command = words.front();
    process->args.assign(words.begin() + 1, words.end());
    for (const std::string& arg : {std::string("--url"), "ws://127.0.0.1:" + std::to_string(o.view_port),
                                   std::string("--name"), name})
      process->args.push_back(arg);
  }
}

// The run's id: --run-id, else a fresh one (this host runs the arbiter
// unless a --set places it elsewhere; then the id it announces on the URL).
beft::launch::LaunchIdentityRequest identityRequest(const Options& o, const std::string& lcm_url) {
  beft::launch::LaunchIdentityRequest request;
  request.launch_file = o.launch_file;
  request.given_run_id = o.run_id;
  request.lcm_url = lcm_url;
  request.say = [](const std::string& line) {
    std::printf("[run] %s\n", line.c_str());
    std::fflush(stdout);
  };
  return request;
}

// report.json and the pictures, by beft-report; its exit code.
int writeReport(const Options& o, const beft::launch::SupervisorOptions& options, double wall_s, bool log_incomplete) {
  char wall[32];
  std::snprintf(wall, sizeof(wall), "%.3f", wall_s);
  std::vector<std::string> command = {options.bin_dir + "/beft-report", options.record_log, "--scenario",
                                      absolutePath(o.scenario_path), "--out", o.out_dir, "--wall-time", wall};
  if (log_incomplete) command.push_back("--log-incomplete");
  const int code = runProgram(command);
  if (code != 0) std::fprintf(stderr, "[run] error: the report could not be written (code %d)\n", code);
  return code;
}

// With --view: the viewer's port (a free one for 0); false, said, when it is taken.
bool chooseViewPort(Options& o) {
  if (o.view_port == 0) o.view_port = beft::launch::findFreeTcpPort();
  if (o.view_port > 0 && beft::launch::tcpPortFree(o.view_port)) return true;
  std::fprintf(stderr, "[run] error: TCP port %d for --view is taken (another viewer?): give --port N, or 0\n",
               o.view_port);
  return false;
}

// Prints the viewer's URL once its server listens (it starts with the other processes).
void announceViewer(const Options& o) {
  std::thread([port = o.view_port] {
    if (beft::launch::waitForTcpListener("127.0.0.1", port, 60))
      std::printf("[run] view: http://127.0.0.1:%d/\n", port);
    else
      std::printf("[run] warning: the viewer did not start listening on port %d (see processes.log)\n", port);
    std::fflush(stdout);
  }).detach();
}

int runMission(Options& o) {
  beft::scenario::Scenario scenario;
  try {
    scenario = beft::scenario::loadScenario(o.scenario_path);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  if (o.seed < 0) o.seed = static_cast<long long>(scenario.seed);
  if (o.max_ticks < 0) o.max_ticks = static_cast<long long>(std::ceil(scenario.duration / scenario.dt - 1e-9));
  if (o.out_dir.empty()) o.out_dir = std::string(BEFT_SOURCE_DIR) + "/logs/" + scenario.name + "-" + timestamp();
  o.out_dir = absolutePath(o.out_dir);
  std::error_code not_made;
  std::filesystem::create_directories(o.out_dir, not_made);
  if (!std::filesystem::is_directory(o.out_dir, not_made)) {
    std::fprintf(stderr, "[run] error: cannot create the run folder %s\n", o.out_dir.c_str());
    return 1;
  }
  if ((o.view || !o.externals.empty()) && !chooseViewPort(o)) return 1;
  const int port = beft::launch::findFreeUdpPort();
  if (port < 0) {
    std::fprintf(stderr, "[run] error: no free UDP port for LCM\n");
    return 1;
  }
  beft::launch::SupervisorOptions options;
  options.lcm_url = beft::lcmUrlForPort(port);
  options.bin_dir = beft::ownBinDir();
  options.except = {o.except.begin(), o.except.end()};
  options.record_log = o.out_dir + "/run.lcmlog";
  options.record_camera = o.record_camera;
  options.quiet_children = !o.verbose;
  options.output_file = o.out_dir + "/processes.log";
  beft::launch::LaunchSpec spec;
  try {
    for (const auto& kill : o.kills) options.kills.push_back(beft::launch::parsePlannedKill(kill));
    options.key_file = beft::launch::runKeyFile(o.key_file);
    spec = beft::launch::loadLaunchFile(o.launch_file, launchArguments(o, scenario, options.lcm_url));
    useExternalExperts(o, spec);
    const auto identity = beft::launch::identifyLaunch(spec, identityRequest(o, options.lcm_url));
    options.run_id = identity.run_id;
    options.run_origin = identity.origin;
  } catch (const std::exception& e) {  // LaunchError: a bad launch file, --run-id or key
    std::fprintf(stderr, "[run] error: %s\n", e.what());
    return 2;
  }
  std::printf("[run] scenario %s (%s): up to %lld ticks of %.3g s, seed %lld, planner %s\n", scenario.name.c_str(),
              o.scenario_path.c_str(), o.max_ticks, scenario.dt, o.seed, o.planner.c_str());
  std::printf("[run] LCM %s; process output in %s/processes.log\n", options.lcm_url.c_str(), o.out_dir.c_str());
  if (realTimePace(o)) std::printf("[run] real-time pace: a tick of %.3g s takes at least that long\n", scenario.dt);
  if (o.record_camera != "all") std::printf("[run] camera frames recorded: %s\n", o.record_camera.c_str());
  std::fflush(stdout);

  beft::launch::RunOutcome outcome;
  const auto start = std::chrono::steady_clock::now();
  try {
    if (!beft::launch::writeRunParameters(spec, o.out_dir + "/" + beft::launch::kRunParametersFile))
      std::fprintf(stderr, "[run] warning: cannot write %s/%s: a replay will need --param\n", o.out_dir.c_str(),
                   beft::launch::kRunParametersFile);
    if (o.view) announceViewer(o);
    outcome = beft::launch::supervise(spec, options);
  } catch (const beft::launch::LaunchError& e) {
    std::fprintf(stderr, "[run] error: %s\n", e.what());
    return 2;
  }
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const bool worked = outcome.arbiter_ran && outcome.arbiter_exit_code == 0 && !outcome.interrupted;
  std::printf("[run] %s after %.2f s wall time\n", outcome.message.c_str(), wall_s);
  const int report_code =
      o.report && outcome.arbiter_ran ? writeReport(o, options, wall_s, outcome.log_incomplete) : 0;
  if (!worked)
    std::fprintf(stderr, "[run] error: the run did not complete: %s (see %s/processes.log)\n",
                 outcome.message.c_str(), o.out_dir.c_str());
  std::printf("%s\n", o.out_dir.c_str());
  return worked && report_code == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const auto code = parseOptions(argc, argv, options)) return *code;
  return runMission(options);
}
