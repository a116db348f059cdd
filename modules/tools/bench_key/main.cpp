// beft-bench-key: what an authenticated run costs. yard.xml unkeyed and
// keyed (--key), in turns, in one invocation: ticks per second and wall time
// per tick of each, and keyed against unkeyed; then what making and checking
// one message's tag costs by the message's size.
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "lib/common/command_line.hpp"
#include "tools/bench_key/keyed_runs.hpp"
#include "tools/bench_key/tag_cost.hpp"

namespace {

struct Options {
  int ticks = 600, repeat = 3;
  std::string work = (std::filesystem::temp_directory_path() / "beft_bench_key").string();
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app("Runs yard.xml unkeyed and keyed (beft run --key), in turns, and prints each run's ticks per "
               "second, the wall time per tick, and keyed against unkeyed (mean of the runs); then the cost of "
               "making and of checking one message's tag by message size. Figures only: a loaded machine "
               "moves them.",
               "beft-bench-key");
  app.add_option("--ticks", o.ticks, "ticks per run")->capture_default_str()->check(CLI::Range(10, 100000));
  app.add_option("--repeat", o.repeat, "runs of each kind")->capture_default_str()->check(CLI::Range(1, 20));
  app.add_option("--work", o.work, "folder for the runs and the key")->capture_default_str();
  return beft::parseCommandLine(app, argc, argv);
}

struct Totals {
  double ticks_per_s = 0;
  int runs = 0;
  double mean() const { return runs > 0 ? ticks_per_s / runs : 0; }
};

double msPerTick(double ticks_per_s) { return ticks_per_s > 0 ? 1000.0 / ticks_per_s : 0; }

// Unkeyed, keyed, unkeyed, ...: a machine that slows down meanwhile weighs on both.
void runInTurns(const Options& o, const std::string& key, Totals& unkeyed, Totals& keyed) {
  std::printf("%-8s %-4s %9s %9s %11s %8s\n", "yard.xml", "run", "ticks", "ticks/s", "ms per tick", "refused");
  for (int round = 1; round <= o.repeat; ++round)
    for (const bool with_key : {false, true}) {
      const std::string name = with_key ? "keyed" : "unkeyed";
      const auto run = beft::bench::runYard(o.work + "/" + name + "_" + std::to_string(round), o.ticks,
                                            with_key ? key : "");
      std::printf("%-8s %-4d %9lld %9.0f %11.2f %8lld%s\n", name.c_str(), round, run.ticks, run.ticks_per_s,
                  msPerTick(run.ticks_per_s), run.refused, run.completed_run ? "" : "  (the run failed)");
      std::fflush(stdout);
      if (!run.completed_run) continue;
      Totals& totals = with_key ? keyed : unkeyed;
      totals.ticks_per_s += run.ticks_per_s;
      ++totals.runs;
    }
}

void printTagCosts() {
  std::printf("\none message's tag (keyed BLAKE2b, libsodium):\n%10s %12s %12s\n", "bytes", "make [us]", "check [us]");
  for (const std::size_t bytes : {64u, 1024u, 8192u, 65536u}) {
    const auto cost = beft::bench::measureTagCost(bytes, bytes >= 8192 ? 2000 : 20000);
    std::printf("%10zu %12.2f %12.2f\n", cost.bytes, cost.make_us, cost.check_us);
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (const auto code = parseOptions(argc, argv, o)) return *code;
  std::filesystem::create_directories(o.work);
  const std::string key = o.work + "/run.key";
  if (!beft::bench::makeKey(key)) {
    std::fprintf(stderr, "beft-bench-key: error: beft-key could not write %s\n", key.c_str());
    return 1;
  }
  Totals unkeyed, keyed;
  runInTurns(o, key, unkeyed, keyed);
  if (unkeyed.runs > 0 && keyed.runs > 0)
    std::printf("\nkeyed / unkeyed: %.3f of the ticks per second (%.0f against %.0f); %+.2f ms per tick\n",
                keyed.mean() / unkeyed.mean(), keyed.mean(), unkeyed.mean(),
                msPerTick(keyed.mean()) - msPerTick(unkeyed.mean()));
  printTagCosts();
  std::printf("runs in %s\n", o.work.c_str());
  return 0;
}
