// beft-bench-faults: yard.xml clean, then under faults, each run compared
// with the clean run message by message: malformed traffic at 3000
// messages/s on its own channels, another run's messages on its URL, every
// expert killed once at a random tick, the clean run's log played on the URL
// at full speed, a keyed run with an unkeyed sender beside it, and the
// experts on a second host (a network namespace) over a link that loses 0,
// 1, 5 and 10 % of the datagrams each way.
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "lib/common/command_line.hpp"
#include "tools/bench_faults/data_messages.hpp"
#include "tools/bench_faults/lossy_link_rows.hpp"
#include "tools/bench_faults/one_host_rows.hpp"
#include "tools/bench_faults/outcome.hpp"
#include "tools/bench_faults/yard_run.hpp"

namespace {

using beft::bench::Outcome;

struct Options {
  int ticks = 560;
  uint64_t seed = 1;
  std::string work = "/tmp/beft_bench_faults";
  std::vector<double> losses = {0, 0.01, 0.05, 0.10};
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app("Runs yard.xml clean and under faults and compares every data message with the clean run: "
               "malformed traffic at 3000 messages/s on the run's channels, another run's messages on its URL, "
               "every expert SIGKILLed once at a random tick (restarted, resuming from the log), the clean run's "
               "log played on the URL at full speed (lcm-logplayer), a keyed run (--key) with an unkeyed sender "
               "of its own messages, and the experts on a second host (a network namespace; needs root and "
               "iptables) over a link that drops each --loss of the datagrams each way. For each: completed, "
               "data messages as the clean run, messages refused, the recorder's loss repair (missed at first, "
               "repaired, lost; whether its log is complete) and ticks/s; then the ticks/s at 5 % loss over "
               "those at 0 % loss on the same two hosts.",
               "beft-bench-faults");
  app.add_option("--ticks", o.ticks, "ticks per run")->capture_default_str();
  app.add_option("--seed", o.seed, "seed of the kill ticks")->capture_default_str();
  app.add_option("--work", o.work, "folder for the runs")->capture_default_str();
  app.add_option("--loss", o.losses, "shares of the datagrams the two hosts' link drops each way, one run each")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
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

// The seed beft-run said it ran with ("[run] scenario ...: ..., seed N, ...").
uint64_t seedOfRun(const std::string& output) {
  const std::string line = beft::bench::lineAfter(output, "[run] scenario ");
  const auto at = line.find(", seed ");
  return at == std::string::npos ? 0 : std::strtoull(line.c_str() + at + 7, nullptr, 10);
}

void printAll(const std::vector<Outcome>& outcomes, const std::string& kills, const std::string& work) {
  beft::bench::printOutcomes(outcomes);
  std::printf("missed, repaired, lost: the recorder's loss repair (messages it missed at first and asked for, "
              "got again, never got); log full: its final account of the log\n");
  for (const auto& o : outcomes)
    if (o.loss >= 0 && o.skipped.empty())
      std::printf("%s: %llu datagrams dropped by the link\n", o.name.c_str(),
                  static_cast<unsigned long long>(o.dropped_datagrams));
  const std::string ratio = beft::bench::speedRatioLine(outcomes, 0.05, 0.0);
  std::printf("%s\n", ratio.empty() ? "ticks/s at 5 % loss / at 0 % loss: not measured (a row is missing)"
                                     : ratio.c_str());
  std::printf("kills:%s\nruns in %s\n", kills.c_str(), work.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (const auto code = parseOptions(argc, argv, o)) return *code;
  const std::string kills = killEveryExpert(o.seed, o.ticks);
  const std::string clean_dir = o.work + "/clean";
  std::vector<Outcome> outcomes = {beft::bench::runYard("clean", clean_dir, "", o.ticks, nullptr)};
  outcomes.back().identical = "(reference)";
  const auto clean = beft::bench::dataMessages(clean_dir + "/run.lcmlog", outcomes.back().run_id);
  for (auto& row : beft::bench::runOnOneHost({o.work, clean_dir + "/run.lcmlog", o.ticks, kills}, clean))
    outcomes.push_back(row);
  const uint64_t seed = seedOfRun(beft::bench::readFile(clean_dir + "/out.txt"));
  for (auto& row : beft::bench::runOverLossyLink({o.losses, o.work, seed, o.ticks}, clean)) outcomes.push_back(row);
  printAll(outcomes, kills, o.work);
  return 0;
}
