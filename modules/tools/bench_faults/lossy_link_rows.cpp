#include "tools/bench_faults/lossy_link_rows.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "lib/common/own_bin_dir.hpp"
#include "tests/system/two_hosts.hpp"
#include "tools/bench_faults/data_messages.hpp"
#include "tools/bench_faults/yard_run.hpp"

namespace beft::bench {

namespace {

using system_test::TwoHosts;

int percentOf(double loss) { return static_cast<int>(std::lround(loss * 100)); }

std::string rowName(double loss) { return "two hosts, " + std::to_string(percentOf(loss)) + " % loss"; }

std::string firstLine(const std::string& text) { return text.substr(0, text.find('\n')); }

// One distributed run in `dir` at `loss`, its report written by beft-report.
Outcome runOnce(TwoHosts& hosts, double loss, const std::string& dir, const LinkRuns& runs,
                const std::vector<compare::LoggedMessage>& clean) {
  Outcome outcome;
  outcome.name = rowName(loss);
  outcome.loss = loss;
  if (const std::string why = hosts.dropIncoming(loss); !why.empty()) {
    outcome.skipped = "skipped: " + firstLine(why);
    return outcome;
  }
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  system_test::DistributedMission mission;
  mission.bin_dir = ownBinDir();
  mission.source_dir = BEFT_SOURCE_DIR;
  mission.dir = dir;
  mission.seed = runs.seed;
  mission.max_ticks = runs.ticks;
  const int code = runShell("(" + system_test::distributedMissionCommand(hosts, mission) + ") > " + dir +
                                "/out.txt 2>&1",
                            120 + runs.ticks);
  outcome.dropped_datagrams = hosts.droppedDatagrams();
  hosts.stopEverythingInside();
  runShell(ownBinDir() + "/beft-report " + dir + "/run.lcmlog --scenario " + BEFT_SOURCE_DIR +
               "/scenarios/yard.xml --quiet --out " + dir + " > " + dir + "/report.txt 2>&1",
           120);
  const std::string output = readFile(dir + "/out.txt");
  readRun(dir + "/report.json", output, outcome);
  outcome.run_id = runIdIn(readFile(dir + "/sim.log"));
  if (code != 0) {
    outcome.completed = false;
    const std::string how = code < 0 ? "timed out" : "exit " + std::to_string(code);
    outcome.identical = "no: the run failed (" + how + "; " + dir + "/out.txt)";
  } else {
    outcome.identical = compareRuns(clean, dir + "/run.lcmlog", outcome.run_id);
  }
  return outcome;
}

}  // namespace

std::vector<Outcome> runOverLossyLink(const LinkRuns& runs, const std::vector<compare::LoggedMessage>& clean) {
  std::vector<Outcome> rows;
  std::string why_not;
  const std::unique_ptr<TwoHosts> hosts = TwoHosts::create(why_not);
  for (const double loss : runs.losses) {
    if (!hosts) {
      Outcome skipped;
      skipped.name = rowName(loss);
      skipped.loss = loss;
      skipped.skipped = "skipped: " + firstLine(why_not);
      rows.push_back(skipped);
      continue;
    }
    rows.push_back(runOnce(*hosts, loss, runs.work + "/link_" + std::to_string(percentOf(loss)), runs, clean));
  }
  return rows;
}

std::string speedRatioLine(const std::vector<Outcome>& rows, double lossy, double clean) {
  const Outcome *at_lossy = nullptr, *at_clean = nullptr;
  for (const auto& row : rows) {
    if (!row.skipped.empty() || row.ticks_per_s <= 0) continue;
    if (percentOf(row.loss) == percentOf(lossy) && row.loss >= 0) at_lossy = &row;
    if (percentOf(row.loss) == percentOf(clean) && row.loss >= 0) at_clean = &row;
  }
  if (!at_lossy || !at_clean) return "";
  char line[200];
  std::snprintf(line, sizeof line, "ticks/s at %d %% loss / at %d %% loss, same two hosts: %.0f / %.0f = %.2f",
                percentOf(lossy), percentOf(clean), at_lossy->ticks_per_s, at_clean->ticks_per_s,
                at_lossy->ticks_per_s / at_clean->ticks_per_s);
  return line;
}

}  // namespace beft::bench
