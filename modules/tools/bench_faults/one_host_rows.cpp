#include "tools/bench_faults/one_host_rows.hpp"

#include <filesystem>

#include "lib/common/own_bin_dir.hpp"
#include "tools/bench_faults/data_messages.hpp"
#include "tools/bench_faults/yard_run.hpp"

namespace beft::bench {

namespace {

// beft-inject with `args` beside a run; without the run's key, if it has one.
pid_t startInjector(const std::string& args) {
  return startShell("exec env -u BEFT_KEY_FILE " + ownBinDir() + "/beft-inject " + args + " > /dev/null 2>&1");
}

// lcm-logplayer playing `log` on `url` as fast as it can, again and again.
pid_t startLogPlayer(const std::string& log, const std::string& url) {
  return startShell("while :; do lcm-logplayer --speed=1000000 --lcm-url='" + url + "' " + log +
                    " > /dev/null 2>&1 || sleep 0.1; done");
}

// Why a keyed run cannot be made with these programs; "" when it can.
std::string whyNoKeyedRun(const std::string& key_file) {
  const std::string bin = ownBinDir();
  if (!std::filesystem::exists(bin + "/beft-key")) return "no beft-key beside this program";
  if (runShell(bin + "/beft-run --help | grep -q -- --key", 30) != 0) return "beft-run takes no --key";
  std::filesystem::remove(key_file);
  if (runShell(bin + "/beft-key new " + key_file + " > /dev/null 2>&1", 30) != 0) return "beft-key new failed";
  return "";
}

Outcome keyedRun(const OneHostRuns& runs) {
  const std::string name = "keyed, unkeyed sender";
  const std::string key_file = runs.work + "/run.key";
  if (const std::string why = whyNoKeyedRun(key_file); !why.empty()) {
    Outcome outcome;
    outcome.name = name;
    outcome.skipped = "not available: " + why;
    return outcome;
  }
  // Copies of the run's own messages, on its channels, with envelopes but no tag.
  return runYard(name, runs.work + "/keyed", "--key " + key_file, runs.ticks,
                 [&](const std::string& url, const std::string& run) {
                   return startInjector(runs.clean_log + " --lcm-url '" + url + "' --rate 3000 --as-is --into-run " +
                                        run);
                 });
}

}  // namespace

std::vector<Outcome> runOnOneHost(const OneHostRuns& runs, const std::vector<compare::LoggedMessage>& clean) {
  std::vector<Outcome> outcomes;
  const std::string& work = runs.work;
  auto compared = [&](Outcome outcome, const std::string& dir) {
    if (outcome.skipped.empty()) outcome.identical = compareRuns(clean, dir + "/run.lcmlog", outcome.run_id);
    outcomes.push_back(outcome);
  };
  compared(runYard("malformed 3000/s", work + "/malformed", "", runs.ticks,
                   [&](const std::string& url, const std::string& run) {
                     return startInjector(runs.clean_log + " --lcm-url '" + url +
                                          "' --rate 3000 --damage malformed --into-run " + run);
                   }),
           work + "/malformed");
  compared(runYard("another run", work + "/other", "", runs.ticks,
                   [&](const std::string& url, const std::string&) {
                     return startInjector(runs.clean_log + " --lcm-url '" + url +
                                          "' --rate 3000 --as-is --into-run 1234");
                   }),
           work + "/other");
  compared(runYard("every expert killed", work + "/killed", runs.kills, runs.ticks, nullptr), work + "/killed");
  compared(runYard("earlier log replayed", work + "/replayed", "", runs.ticks,
                   [&](const std::string& url, const std::string&) { return startLogPlayer(runs.clean_log, url); }),
           work + "/replayed");
  compared(keyedRun(runs), work + "/keyed");
  return outcomes;
}

}  // namespace beft::bench
