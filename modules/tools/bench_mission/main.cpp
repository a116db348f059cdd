// beft-bench-mission (./beft bench mission): how fast a whole mission runs.
// Runs `beft-run` on a scenario several times, as shipped and with one
// measure turned off at a time (the direct receiver, BEFT_UDPM_RECEIVER=0:
// LCM's own receive thread with the kernel channel filter, as before it; the
// arbiter's poll for DONE, BEFT_ARBITER_SPIN_US=0; the background priority of
// the recorder and blackboard, BEFT_BACKGROUND=0; the heap kept between
// firings, BEFT_RETAIN_HEAP=0), and with the dynamic-weighting expert
// replaced by its Python port (modules/python/examples/dw_expert.py, through
// the run's bridge), alternately so that all share the machine's state, and
// prints ticks per second, times real time and each baseline's ratio to the
// shipped setup.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "lib/common/command_line.hpp"
#include "lib/common/own_bin_dir.hpp"

extern char** environ;

namespace {

struct RunFigures {
  bool ok = false;
  double ticks_per_s = 0, times_real_time = 0, overall_times_real_time = 0;
  bool completed = false;
};

// One setup of the run: its name, the environment setting it adds and the
// arguments it adds to beft-run.
struct Variant {
  std::string name, setting;  // setting: "" or NAME=VALUE
  std::vector<std::string> run_args = {};
};

// Debian's interpreter: the one that sees Debian's python3-websockets.
const char* const kPython = "/usr/bin/python3";
const std::string kPythonDw =
    std::string("dw=") + kPython + " " + BEFT_SOURCE_DIR + "/modules/python/examples/dw_expert.py";

const char* const kSettingsUnderTest[] = {"BEFT_UDPM_RECEIVER=", "BEFT_UDPM_FILTER=", "BEFT_ARBITER_SPIN_US=",
                                          "BEFT_BACKGROUND=", "BEFT_RETAIN_HEAP="};

RunFigures runOnce(const std::string& scenario, const std::string& net, const std::string& out_dir,
                   const Variant& variant) {
  RunFigures figures;
  std::vector<std::string> args = {beft::ownBinDir() + "/beft-run", scenario, "--out", out_dir};
  if (!net.empty()) args.insert(args.end(), {"--net", net});
  args.insert(args.end(), variant.run_args.begin(), variant.run_args.end());
  std::vector<char*> argv;
  for (auto& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  // The measures under test take their setting from here only.
  std::vector<std::string> environment;
  for (char** e = environ; *e; ++e) {
    const std::string entry = *e;
    bool under_test = false;
    for (const char* name : kSettingsUnderTest) under_test = under_test || entry.rfind(name, 0) == 0;
    if (!under_test) environment.push_back(entry);
  }
  if (!variant.setting.empty()) environment.push_back(variant.setting);
  std::vector<char*> envp;
  for (auto& entry : environment) envp.push_back(entry.data());
  envp.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return figures;
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return figures;
  std::ifstream file(out_dir + "/report.json");
  try {
    const auto report = nlohmann::json::parse(file);
    figures.ticks_per_s = report.at("ticks_per_s").get<double>();
    figures.times_real_time = report.at("realtime_factor").get<double>();
    figures.overall_times_real_time = report.at("overall_realtime_factor").get<double>();
    figures.completed = report.at("completed").get<bool>();
    figures.ok = true;
  } catch (const std::exception&) {
  }
  return figures;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

struct Options {
  std::string scenario = "scenarios/yard.xml";
  std::string net;
  int runs = 3;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app{
      "beft-bench-mission: runs the whole mission (every process, lockstep, recorded) on a scenario "
      "several times: as shipped, with LCM's own receive thread instead of the direct receiver "
      "(BEFT_UDPM_RECEIVER=0), without the arbiter's poll for DONE (BEFT_ARBITER_SPIN_US=0), without the "
      "background priority of the recorder and blackboard (BEFT_BACKGROUND=0) and with freed memory given "
      "back to the kernel at once, glibc's default (BEFT_RETAIN_HEAP=0), and with the dw expert replaced by "
      "its Python port through the run's bridge (--external dw=..., needs Debian's python3-websockets), one "
      "after the other, and prints the median ticks per second and times real time of each and each one's ratio to the shipped "
      "setup. Target: >= 50x real time on yard.xml."};
  app.add_option("scenario", o.scenario, "scenario XML file")->capture_default_str()->check(CLI::ExistingFile);
  app.add_option("--net", o.net, "Petri net of the schedule (default: the run's, scenarios/nets/default.pnml)")
      ->check(CLI::ExistingFile);
  app.add_option("--runs", o.runs, "runs of each setup")->capture_default_str()->check(CLI::Range(1, 100));
  if (const auto code = beft::parseCommandLine(app, argc, argv)) return code;
  return std::nullopt;
}

const std::vector<Variant> kVariants = {{"as shipped", ""},
                                        {"LCM receive", "BEFT_UDPM_RECEIVER=0"},
                                        {"no DONE poll", "BEFT_ARBITER_SPIN_US=0"},
                                        {"no background", "BEFT_BACKGROUND=0"},
                                        {"heap given back", "BEFT_RETAIN_HEAP=0"},
                                        {"Python dw", "", {"--external", kPythonDw}}};

// Per setup: ticks per second, times real time, and the same with start and stop.
struct Figures {
  std::vector<std::vector<double>> rate, real, overall;
  int failures = 0;
};

// The setups alternated, run after run, so a busy spell of the machine
// falls on all of them.
Figures runSetups(const Options& o) {
  const auto& variants = kVariants;
  const std::string& scenario = o.scenario;
  const std::string& net = o.net;
  const int runs = o.runs;
  Figures f{std::vector<std::vector<double>>(variants.size()), std::vector<std::vector<double>>(variants.size()),
            std::vector<std::vector<double>>(variants.size()), 0};
  auto& rate = f.rate;
  auto& real = f.real;
  auto& overall = f.overall;
  int& failures = f.failures;
  const auto work = std::filesystem::temp_directory_path() / ("beft-bench-mission-" + std::to_string(getpid()));
  for (int i = 0; i < runs; ++i) {
    for (std::size_t v = 0; v < variants.size(); ++v) {
      const auto out = work / ("setup" + std::to_string(v) + "-run" + std::to_string(i));
      const RunFigures figures = runOnce(scenario, net, out.string(), variants[v]);
      if (!figures.ok) {
        std::fprintf(stderr, "run %d (%s) failed: see %s/processes.log\n", i + 1, variants[v].name.c_str(),
                     out.c_str());
        ++failures;
        continue;
      }
      std::printf("  run %d %-16s %6.0f ticks/s  %5.1fx real time (%4.1fx with start and stop)%s\n", i + 1,
                  variants[v].name.c_str(), figures.ticks_per_s, figures.times_real_time,
                  figures.overall_times_real_time, figures.completed ? "" : "  (mission not completed)");
      std::fflush(stdout);
      rate[v].push_back(figures.ticks_per_s);
      real[v].push_back(figures.times_real_time);
      overall[v].push_back(figures.overall_times_real_time);
      std::filesystem::remove_all(out);
    }
  }
  std::filesystem::remove_all(work);
  return f;
}

void printMedians(const Options& o, const Figures& f) {
  const auto& variants = kVariants;
  const auto& rate = f.rate;
  const auto& real = f.real;
  const auto& overall = f.overall;
  std::printf("%s%s, median of %d runs each (lockstep loop; in brackets with every process started and stopped):\n",
              o.scenario.c_str(), o.net.empty() ? "" : (" with " + o.net).c_str(), o.runs);
  for (std::size_t v = 0; v < variants.size(); ++v) {
    std::printf("  %-16s %6.0f ticks/s  %5.1fx real time (%4.1fx)", variants[v].name.c_str(), median(rate[v]),
                median(real[v]), median(overall[v]));
    if (v > 0 && median(rate[v]) > 0) std::printf("   shipped / this: %.2f", median(rate[0]) / median(rate[v]));
    std::printf("\n");
  }
  std::printf("  target         >= 50x real time\n");
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const auto code = parseOptions(argc, argv, options)) return *code;
  const Figures figures = runSetups(options);
  printMedians(options, figures);
  return figures.failures ? 1 : 0;
}
