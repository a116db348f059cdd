// beft-bench-faults: yard.xml clean, then with malformed traffic at 3000
// messages/s on its own channels, with another run's messages on its URL,
// and with every expert killed once at a random tick; each compared with
// the clean run message by message.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "lib/common/command_line.hpp"
#include "tools/bench_faults/data_messages.hpp"
#include "lib/common/own_bin_dir.hpp"
#include "lib/wire/run_identity.hpp"

namespace {

struct Outcome {
  std::string name;
  bool completed = false;
  std::string identical;
  long long rejected = 0, other_run = 0, restarts = 0;
  double ticks_per_s = 0;
  int64_t run_id = 0;  // as beft run printed it: other runs share the log
};

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

std::string lineAfter(const std::string& text, const std::string& prefix) {
  const auto at = text.find(prefix);
  return at == std::string::npos ? "" : text.substr(at + prefix.size(), text.find('\n', at) - at - prefix.size());
}

// One yard run in `dir`; `during` runs beside it once its URL and run id are printed.
Outcome runYard(const std::string& name, const std::string& dir, const std::string& args, int ticks,
                const std::function<pid_t(const std::string& url, const std::string& run_id)>& during) {
  const std::string bin = beft::ownBinDir();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const pid_t runner = fork();
  if (runner == 0) {
    const std::string command = bin + "/beft-run " + BEFT_SOURCE_DIR + "/scenarios/yard.xml --max-ticks " +
                                std::to_string(ticks) + " --out " + dir + " " + args + " > " + dir + "/out.txt 2>&1";
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  pid_t helper = -1;
  if (during) {
    std::string url, run_id;
    for (int i = 0; i < 500 && (url.empty() || run_id.empty()); ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      const std::string out = readFile(dir + "/out.txt");
      url = lineAfter(out, "[run] LCM ");
      url = url.substr(0, url.find(';'));
      const std::string started = lineAfter(out, "[launch] started ");
      if (const auto at = started.find(" as run "); at != std::string::npos) run_id = started.substr(at + 8);
    }
    helper = during(url, run_id);
  }
  int status = 0;
  waitpid(runner, &status, 0);
  if (helper > 0) {
    kill(helper, SIGTERM);
    waitpid(helper, nullptr, 0);
  }
  Outcome outcome;
  outcome.name = name;
  const std::string started = lineAfter(readFile(dir + "/out.txt"), "[launch] started ");
  if (const auto at = started.find(" as run "); at != std::string::npos)
    outcome.run_id = beft::wire::parseRunId(started.substr(at + 8));
  try {
    const auto report = nlohmann::json::parse(readFile(dir + "/report.json"));
    outcome.completed = report.value("completed", false);
    outcome.rejected = report.value("rejected_total", 0LL);
    outcome.other_run = report.value("other_run_messages", 0LL);
    outcome.ticks_per_s = report.value("ticks_per_s", 0.0);
  } catch (const std::exception&) {
  }
  const std::string processes = readFile(dir + "/processes.log");
  for (auto at = processes.find(": restarting ("); at != std::string::npos; at = processes.find(": restarting (", at + 1))
    ++outcome.restarts;
  return outcome;
}

pid_t startInjector(const std::string& args) {
  const pid_t pid = fork();
  if (pid == 0) {
    const std::string command = "exec " + beft::ownBinDir() + "/beft-inject " + args + " > /dev/null 2>&1";
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

struct Options {
  int ticks = 560;
  uint64_t seed = 1;
  std::string work = "/tmp/beft_bench_faults";
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app("Runs yard.xml clean and under faults and compares every data message with the clean run: "
               "malformed traffic at 3000 messages/s on the run's channels, another run's messages on its URL, "
               "every expert SIGKILLed once at a random tick (restarted, resuming from the log).",
               "beft-bench-faults");
  app.add_option("--ticks", o.ticks, "ticks per run")->capture_default_str();
  app.add_option("--seed", o.seed, "seed of the kill ticks")->capture_default_str();
  app.add_option("--work", o.work, "folder for the runs")->capture_default_str();
  return beft::parseCommandLine(app, argc, argv);
}

// beft-run arguments that kill every expert once, each at a random tick.
std::string killEveryExpert(uint64_t seed, int ticks) {
  std::mt19937_64 random(seed);
  std::string kills;
  for (const char* expert : {"world", "vision", "geometry", "audio", "visual_labels", "acoustic_labels", "fusion",
                             "dw", "exploration", "tasks"})
    kills += " --kill " + std::string(expert) + "@" + std::to_string(10 + random() % (ticks - 20));
  return kills;
}

// The clean run, then each fault run compared with it message by message.
std::vector<Outcome> runCleanAndFaulty(const Options& o, const std::string& kills) {
  std::vector<Outcome> outcomes;
  const std::string& work = o.work;
  const std::string clean_dir = work + "/clean";
  outcomes.push_back(runYard("clean", clean_dir, "", o.ticks, nullptr));
  const auto clean = beft::bench::dataMessages(clean_dir + "/run.lcmlog", outcomes.back().run_id);
  auto compare = [&](Outcome outcome, const std::string& dir) {
    outcome.identical = beft::bench::compareRuns(clean, dir + "/run.lcmlog", outcome.run_id);
    outcomes.push_back(outcome);
  };
  outcomes.back().identical = "(reference)";
  compare(runYard("malformed 3000/s", work + "/malformed", "", o.ticks,
                  [&](const std::string& url, const std::string& run) {
                    return startInjector(clean_dir + "/run.lcmlog --lcm-url '" + url +
                                         "' --rate 3000 --damage malformed --into-run " + run);
                  }),
          work + "/malformed");
  compare(runYard("another run", work + "/other", "", o.ticks,
                  [&](const std::string& url, const std::string&) {
                    return startInjector(clean_dir + "/run.lcmlog --lcm-url '" + url +
                                         "' --rate 3000 --as-is --into-run 1234");
                  }),
          work + "/other");
  compare(runYard("every expert killed", work + "/killed", kills, o.ticks, nullptr), work + "/killed");
  return outcomes;
}

void printOutcomes(const std::vector<Outcome>& outcomes, const std::string& kills, const std::string& work) {
  std::printf("%-22s %-9s %-40s %9s %9s %8s %9s\n", "yard.xml", "completed", "data messages as the clean run",
              "rejected", "other run", "restarts", "ticks/s");
  for (const auto& o : outcomes)
    std::printf("%-22s %-9s %-40s %9lld %9lld %8lld %9.0f\n", o.name.c_str(), o.completed ? "yes" : "no",
                o.identical.c_str(), o.rejected, o.other_run, o.restarts, o.ticks_per_s);
  std::printf("kills:%s\nruns in %s\n", kills.c_str(), work.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (const auto code = parseOptions(argc, argv, o)) return *code;
  const std::string kills = killEveryExpert(o.seed, o.ticks);
  const std::vector<Outcome> outcomes = runCleanAndFaulty(o, kills);
  printOutcomes(outcomes, kills, o.work);
  return 0;
}
